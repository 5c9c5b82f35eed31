#include "seam_away.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <optional>
#include <sstream>

namespace semimesh::occ {
namespace {

// Whether the face wraps its surface's whole period in U (or V): its one wire holds a seam edge, an
// iso-line of that parameter used twice.
bool wraps_around(const TopoDS_Face& face, bool in_u) {
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return false;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (!BRep_Tool::IsClosed(edge, face)) continue;
    double first, last;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull()) continue;
    const gp_Pnt2d a = pcurve->Value(first), b = pcurve->Value(last);
    // A seam of the closed U direction is a line of constant u.
    if (in_u ? std::abs(a.X() - b.X()) < Precision::PConfusion() : std::abs(a.Y() - b.Y()) < Precision::PConfusion())
      return true;
  }
  return false;
}

// The surface re-parametrised so that its closed parameter (U when `in_u`) starts at `origin`;
// nothing for a kind that cannot be (yet: B-splines).
Handle(Geom_Surface) started_at(const Handle(Geom_Surface)& surface, bool in_u, double origin) {
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  // B-spline surfaces are not re-seamed: made periodic with a knot at the new seam as origin (then
  // clamped again), a rational body of revolution (write_wing_variant fuselage_bspline_unjoined)
  // meshed at order 2, but at orders 3-4 the wall layer's prisms folded a few degrees from the new
  // seam (their nodes on the wall, curving's placement near it). Such a wall keeps its seam and
  // the roles refuse it by name, as a file already joined with its seam through the root.
  // Cylinders, cones, spheres, tori and surfaces of revolution: U is the angle about their axis
  // from their reference direction; turning the surface about its axis by `origin` moves the seam
  // there and leaves the shape as it was.
  if (!in_u) return nullptr;
  if (auto elementary = Handle(Geom_ElementarySurface)::DownCast(surface->Copy())) {
    elementary->Rotate(elementary->Axis(), origin - u0);
    return elementary;
  }
  if (auto revolution = Handle(Geom_SurfaceOfRevolution)::DownCast(surface->Copy())) {
    revolution->Rotate(revolution->Axis(), origin - u0);
    return revolution;
  }
  return nullptr;
}

// The face rebuilt with its seam half a period from `away_from`'s foot, or nothing when it does not
// wrap around, its seam lies a quarter of a period or more from the foot already, or its surface
// cannot be re-parametrised.
std::optional<TopoDS_Face> reseamed(const TopoDS_Face& face, const gp_Pnt& away_from, double tolerance) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
  double su0, su1, sv0, sv1;
  surface->Bounds(su0, su1, sv0, sv1);
  const bool closed_u = (surface->IsUClosed() || surface->IsUPeriodic()) && wraps_around(face, true);
  const bool closed_v = !closed_u && (surface->IsVClosed() || surface->IsVPeriodic()) && wraps_around(face, false);
  if (!closed_u && !closed_v) return std::nullopt;
  GeomAPI_ProjectPointOnSurf foot(away_from, surface);
  if (foot.NbPoints() == 0) return std::nullopt;
  double u, v;
  foot.LowerDistanceParameters(u, v);
  const double lo = closed_u ? su0 : sv0, period = closed_u ? su1 - su0 : sv1 - sv0;
  const double foot_at = closed_u ? u : v;
  // Already on the far side (a quarter of a turn or more from the foot): kept as it is.
  const double from_seam = std::fmod(std::fmod(foot_at - lo, period) + period, period);
  if (std::min(from_seam, period - from_seam) >= 0.25 * period) return std::nullopt;
  const double origin = lo + std::fmod(from_seam + 0.5 * period, period);
  const Handle(Geom_Surface) moved = started_at(surface, closed_u, origin);
  if (moved.IsNull()) return std::nullopt;
  // The face's own extent along the other parameter; the whole new period along the closed one.
  double fu0, fu1, fv0, fv1, mu0, mu1, mv0, mv1;
  BRepTools::UVBounds(face, fu0, fu1, fv0, fv1);
  moved->Bounds(mu0, mu1, mv0, mv1);
  BRepBuilderAPI_MakeFace make = closed_u ? BRepBuilderAPI_MakeFace(moved, mu0, mu1, fv0, fv1, tolerance)
                                          : BRepBuilderAPI_MakeFace(moved, fu0, fu1, mv0, mv1, tolerance);
  if (!make.IsDone()) return std::nullopt;
  TopoDS_Face out = make.Face();
  if (face.Orientation() == TopAbs_REVERSED) out.Reverse();
  return out;
}

}  // namespace

TopoDS_Shape with_seams_away_from(const TopoDS_Shape& part, const gp_Pnt& away_from, double tolerance,
                                  std::vector<std::string>& repairs) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  int moved = 0;
  for (TopExp_Explorer f(part, TopAbs_FACE); f.More(); f.Next()) {
    const std::optional<TopoDS_Face> face = reseamed(TopoDS::Face(f.Current()), away_from, tolerance);
    sewing.Add(face ? *face : f.Current());
    moved += face.has_value();
  }
  if (moved == 0) return part;
  sewing.Perform();
  std::ostringstream point;
  point << "(" << away_from.X() << ", " << away_from.Y() << ", " << away_from.Z() << ")";
  repairs.push_back("moved the seam of " + std::to_string(moved) + " face(s) of the wall part to their far side from " +
                    "the body (at " + point.str() + ")");
  return sewing.SewedShape();
}

}  // namespace semimesh::occ
