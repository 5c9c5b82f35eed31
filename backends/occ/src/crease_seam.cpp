#include "crease_seam.hpp"

#include "faces_replaced.hpp"
#include "parameter_rectangle.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <optional>
#include <utility>

namespace semimesh::occ {
namespace {

// The surface's unit normal (du x dv) at (u, v), or nothing where it degenerates.
std::optional<gp_Vec> unit_normal(const Handle(Geom_Surface)& s, double u, double v) {
  gp_Pnt p;
  gp_Vec du, dv;
  s->D1(u, v, p, du, dv);
  const gp_Vec n = du.Crossed(dv);
  if (n.Magnitude() <= 1e-12 * du.Magnitude() * dv.Magnitude() || n.Magnitude() == 0.0) return std::nullopt;
  return n.Normalized();
}

// The two halves of `face` split across parameter `along_u` (true: the seam is a u = const line)
// halfway round, when its seam along that parameter is a crease.
std::optional<std::pair<TopoDS_Face, TopoDS_Face>> crease_halves(const TopoDS_Face& face, double tolerance) {
  if (!has_seam(face)) return std::nullopt;
  if (!is_parameter_rectangle(face, tolerance)) return std::nullopt;
  const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  for (const bool along_u : {true, false}) {
    if (!(along_u ? s->IsUClosed() || s->IsUPeriodic() : s->IsVClosed() || s->IsVPeriodic())) continue;
    const double a0 = along_u ? u0 : v0, a1 = along_u ? u1 : v1, b0 = along_u ? v0 : u0, b1 = along_u ? v1 : u1;
    bool crease = true;
    int samples = 0;
    for (int k = 1; k < 8 && crease; ++k) {
      const double b = b0 + k / 8.0 * (b1 - b0);
      const auto first = along_u ? unit_normal(s, a0, b) : unit_normal(s, b, a0);
      const auto last = along_u ? unit_normal(s, a1, b) : unit_normal(s, b, a1);
      if (!first || !last) continue;
      ++samples;
      crease = first->Dot(*last) < std::cos(20.0 * M_PI / 180.0);
    }
    if (!crease || samples == 0) continue;
    const double am = 0.5 * (a0 + a1);
    BRepBuilderAPI_MakeFace low(s, along_u ? a0 : u0, along_u ? am : u1, along_u ? v0 : a0, along_u ? v1 : am, tolerance);
    // A copy of the surface for the other half: two faces on one surface handle sharing an edge
    // make it a seam of that surface to OCCT (its two curves on one surface).
    const Handle(Geom_Surface) other = Handle(Geom_Surface)::DownCast(s->Copy());
    BRepBuilderAPI_MakeFace high(other, along_u ? am : u0, along_u ? a1 : u1, along_u ? v0 : am, along_u ? v1 : a1, tolerance);
    if (!low.IsDone() || !high.IsDone()) return std::nullopt;
    TopoDS_Face a = low.Face(), b = high.Face();
    BRepLib::BuildCurves3d(a);
    BRepLib::BuildCurves3d(b);
    if (face.Orientation() == TopAbs_REVERSED) a.Reverse(), b.Reverse();
    return std::pair{a, b};
  }
  return std::nullopt;
}

}  // namespace

bool has_seam(const TopoDS_Face& face) {
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    if (BRep_Tool::IsClosed(TopoDS::Edge(e.Current()), face)) return true;
  return false;
}

TopoDS_Shape with_crease_seams_split(const TopoDS_Shape& body, double tolerance, FaceNames& names,
                                     std::vector<std::string>& repairs) {
  const FacesReplaced split = with_faces_replaced(body, tolerance, names, [&](const TopoDS_Face& face) {
    const auto halves = crease_halves(face, tolerance);
    return halves ? std::vector<TopoDS_Face>{halves->first, halves->second} : std::vector<TopoDS_Face>{};
  });
  if (split.replaced > 0)
    repairs.push_back("split " + std::to_string(split.replaced) + " body face(s) closed round a sharp edge (a seam along "
                      "the trailing edge) into two halves each, the same surface: the trailing edge a curve between two faces");
  return split.shape;
}

}  // namespace semimesh::occ
