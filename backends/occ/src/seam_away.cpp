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
#include <utility>
#include <sstream>

namespace semimesh::occ {
namespace {

// Whether the face wraps its surface's whole turn in U (in V when `in_v`): its one wire holds a seam
// edge, a line of constant u (v) used twice.
bool wraps_around(const TopoDS_Face& face, bool in_v) {
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
    if (std::abs(in_v ? a.Y() - b.Y() : a.X() - b.X()) < Precision::PConfusion()) return true;
  }
  return false;
}

// A surface turning about an axis (cylinder, cone, sphere, torus, surface of revolution: U is the
// angle from its reference direction) turned by `angle`, so that its seam moves by it and the shape
// stays; a B-spline surface made periodic in U with a knot at `u0 + angle` as its origin (its U
// parameter is not the angle, but a parameter offset all the same); nothing for another kind.
Handle(Geom_Surface) turned(const Handle(Geom_Surface)& surface, double angle) {
  if (auto elementary = Handle(Geom_ElementarySurface)::DownCast(surface->Copy())) {
    elementary->Rotate(elementary->Axis(), angle);
    return elementary;
  }
  if (auto revolution = Handle(Geom_SurfaceOfRevolution)::DownCast(surface->Copy())) {
    revolution->Rotate(revolution->Axis(), angle);
    return revolution;
  }
  if (auto spline = Handle(Geom_BSplineSurface)::DownCast(surface->Copy())) {
    double u0, u1, v0, v1;
    spline->Bounds(u0, u1, v0, v1);
    const double origin = u0 + angle;
    if (!spline->IsUPeriodic()) {
      if (!spline->IsUClosed()) return nullptr;
      spline->SetUPeriodic();
    }
    spline->InsertUKnot(origin, 1, Precision::PConfusion());
    for (int k = 1; k <= spline->NbUKnots(); ++k)
      if (std::abs(spline->UKnot(k) - origin) < Precision::PConfusion()) {
        spline->SetUOrigin(k);
        return spline;
      }
    return nullptr;
  }
  return nullptr;
}

// The face rebuilt with its seam half a turn from `away_from`'s foot, or nothing when it does not
// wrap around, its seam lies a quarter of a turn or more from the foot already, or its surface
// cannot be turned.
std::optional<TopoDS_Face> reseamed(const TopoDS_Face& face, const gp_Pnt& away_from, double tolerance) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
  // A B-spline closed in V only (OpenVSP's bodies of revolution): its parameters exchanged, so that
  // the turn is in U as for every other surface; its normal then flips, and the face with it.
  double fu0, fu1, fv0, fv1;
  BRepTools::UVBounds(face, fu0, fu1, fv0, fv1);
  bool exchanged = false;
  if (auto spline = Handle(Geom_BSplineSurface)::DownCast(surface);
      spline && !(spline->IsUClosed() || spline->IsUPeriodic()) && (spline->IsVClosed() || spline->IsVPeriodic())) {
    spline = Handle(Geom_BSplineSurface)::DownCast(spline->Copy());
    spline->ExchangeUV();
    surface = spline;
    exchanged = true;
    std::swap(fu0, fv0);
    std::swap(fu1, fv1);
  }
  if (!(surface->IsUClosed() || surface->IsUPeriodic()) || !wraps_around(face, exchanged)) return std::nullopt;
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  GeomAPI_ProjectPointOnSurf foot(away_from, surface);
  if (foot.NbPoints() == 0) return std::nullopt;
  double u, v;
  foot.LowerDistanceParameters(u, v);
  const double period = u1 - u0;
  // Already on the far side (a quarter of a turn or more from the foot): kept as it is.
  const double from_seam = std::fmod(std::fmod(u - u0, period) + period, period);
  if (std::min(from_seam, period - from_seam) >= 0.25 * period) return std::nullopt;
  const Handle(Geom_Surface) moved = turned(surface, std::fmod(from_seam + 0.5 * period, period));
  if (moved.IsNull()) return std::nullopt;
  // The whole new turn in U, the face's own extent in V.
  double mu0, mu1, mv0, mv1;
  moved->Bounds(mu0, mu1, mv0, mv1);
  BRepBuilderAPI_MakeFace make(moved, mu0, mu1, fv0, fv1, tolerance);
  if (!make.IsDone()) return std::nullopt;
  TopoDS_Face out = make.Face();
  if ((face.Orientation() == TopAbs_REVERSED) != exchanged) out.Reverse();
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
