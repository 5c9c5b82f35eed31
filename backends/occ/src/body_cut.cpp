#include "body_cut.hpp"

#include "parameter_rectangle.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <sstream>

namespace semimesh::occ {
namespace {

[[noreturn]] void refuse_cut(const std::string& what) { throw cad::CadError(cad::CadError::Kind::BadParameter, what); }

// The least and largest signed distances from the plane of `piece`'s edges (16 points along each):
// after the split a piece lies on one side, touching the plane at most.
std::pair<double, double> side_range(const TopoDS_Shape& piece, const CutPlane& cut) {
  double low = 0.0, high = 0.0;
  for (TopExp_Explorer e(piece, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    for (int k = 0; k <= 16; ++k) {
      const gp_Pnt p = curve.Value(curve.FirstParameter() + k / 16.0 * (curve.LastParameter() - curve.FirstParameter()));
      const double d = gp_Vec(cut.point, p).Dot(gp_Vec(cut.normal));
      low = std::min(low, d);
      high = std::max(high, d);
    }
  }
  return {low, high};
}

// `face`'s part on the plane's near side when the plane holds one of its iso-parameter lines (an
// OpenVSP loft's section at constant span) and the face is the whole of its surface over a parameter rectangle:
// the same surface over the parameter range up to that line, its closed direction sewn into a seam.
// OCCT's surface-plane intersection misses such a section on OpenVSP's pinched wings (the face comes
// out of the split whole); the line is found by bisection on the parameter instead.
std::optional<TopoDS_Shape> iso_trimmed(const TopoDS_Face& face, const CutPlane& cut, double tolerance) {
  if (!is_parameter_rectangle(face, tolerance)) return std::nullopt;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const auto distance = [&](double u, double v) { return gp_Vec(cut.point, surface->Value(u, v)).Dot(gp_Vec(cut.normal)); };
  for (const bool along_u : {true, false}) {
    const double a0 = along_u ? u0 : v0, a1 = along_u ? u1 : v1, b0 = along_u ? v0 : u0, b1 = along_u ? v1 : u1;
    const auto line = [&](double a) {  // the iso-line's mean distance and its spread
      double sum = 0.0, low = 1e300, high = -1e300;
      for (int k = 0; k <= 16; ++k) {
        const double b = b0 + k / 16.0 * (b1 - b0);
        const double d = along_u ? distance(a, b) : distance(b, a);
        sum += d, low = std::min(low, d), high = std::max(high, d);
      }
      return std::pair{sum / 17.0, high - low};
    };
    double lo = a0, hi = a1;
    double g_lo = line(lo).first;
    if ((g_lo > 0.0) == (line(hi).first > 0.0)) continue;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * (std::abs(a1 - a0) + 1.0); ++i) {
      const double mid = 0.5 * (lo + hi);
      const double g = line(mid).first;
      ((g > 0.0) == (g_lo > 0.0) ? lo : hi) = mid;
      if ((g > 0.0) == (g_lo > 0.0)) g_lo = g;
    }
    const double at = 0.5 * (lo + hi);
    if (line(at).second > tolerance) continue;  // the plane crosses the iso-lines: not a section
    const bool keep_low = line(a0).first < 0.0;
    const double k0 = keep_low ? a0 : at, k1 = keep_low ? at : a1;
    BRepBuilderAPI_MakeFace make(surface, along_u ? k0 : u0, along_u ? k1 : u1, along_u ? v0 : k0, along_u ? v1 : k1, tolerance);
    if (!make.IsDone()) return std::nullopt;
    TopoDS_Face part = make.Face();
    BRepLib::BuildCurves3d(part);  // its new edges have curves on the surface only
    if (face.Orientation() == TopAbs_REVERSED) part.Reverse();
    BRepBuilderAPI_Sewing seam(tolerance);
    seam.Add(part);
    seam.Perform();
    return seam.SewedShape();
  }
  return std::nullopt;
}

}  // namespace

// Each face (or solid) of the body is kept, dropped, or when it lies across the plane cut there: a
// face whose iso-parameter section the plane is, in its parameters (iso_trimmed); the rest by OCCT's
// splitter with a face on the plane, its pieces sorted by side here (a Boolean cut classified a
// piece of a degenerate face on the wrong side).
TopoDS_Shape cut_beyond(const TopoDS_Shape& body, const CutPlane& cut, double fuzzy, FaceNames& names) {
  const bool solids = TopExp_Explorer(body, TopAbs_SOLID).More();
  const TopAbs_ShapeEnum piece_kind = solids ? TopAbs_SOLID : TopAbs_FACE;
  const double on_plane = 10.0 * fuzzy;
  TopTools_ListOfShape kept, across;
  int beyond = 0;
  // A piece on the near side is kept, one beyond dropped; true when it lies across.
  const auto sort = [&](const TopoDS_Shape& piece) {
    const auto [low, high] = side_range(piece, cut);
    if (low < -on_plane && high > on_plane) return true;
    if (high > on_plane) ++beyond;
    else kept.Append(piece);
    return false;
  };
  const std::size_t named = names.size();
  for (TopExp_Explorer p(body, piece_kind); p.More(); p.Next()) {
    if (!sort(p.Current())) continue;
    ++beyond;
    const std::optional<TopoDS_Shape> trimmed = solids ? std::nullopt : iso_trimmed(TopoDS::Face(p.Current()), cut, on_plane);
    if (!trimmed) {
      across.Append(p.Current());
      continue;
    }
    for (TopExp_Explorer f(*trimmed, TopAbs_FACE); f.More(); f.Next()) {
      kept.Append(f.Current());
      for (std::size_t i = 0; i < named; ++i)
        if (names[i].first.IsSame(p.Current())) names.emplace_back(f.Current(), names[i].second);
    }
  }
  if (!across.IsEmpty()) {
    Bnd_Box extent;
    BRepBndLib::Add(body, extent);
    const double reach = 2.0 * (std::sqrt(extent.SquareExtent()) + extent.CornerMin().Distance(cut.point) + 1.0);
    BRepAlgoAPI_Splitter split;
    split.SetFuzzyValue(fuzzy);
    TopTools_ListOfShape tools;
    tools.Append(BRepBuilderAPI_MakeFace(gp_Pln(cut.point, cut.normal), -reach, reach, -reach, reach).Face());
    split.SetArguments(across);
    split.SetTools(tools);
    split.Build();
    if (!split.IsDone() || split.HasErrors()) {
      std::ostringstream report;
      split.DumpErrors(report);
      refuse_cut(cut.label + ": OCCT's split of the body by the plane failed: " + report.str());
    }
    for (TopExp_Explorer p(split.Shape(), piece_kind); p.More(); p.Next())
      if (sort(p.Current()))
        refuse_cut(cut.label + ": OCCT's split leaves a " + (solids ? "part" : "face") + " of the body whole across the "
                   "plane, and the plane is not one of its iso-parameter sections");
    for (std::size_t i = 0; i < named; ++i)
      for (const TopoDS_Shape& image : split.Modified(names[i].first)) names.emplace_back(image, names[i].second);
  }
  if (kept.IsEmpty()) refuse_cut(cut.label + ": the plane leaves nothing of the body (it lies wholly beyond it)");
  if (beyond == 0) refuse_cut(cut.label + ": the plane misses the body (no part of it lies beyond it)");

  BRep_Builder builder;
  if (solids) {
    // Each solid kept is closed by the split face (the splitter shares it between the two sides).
    TopoDS_Compound out;
    builder.MakeCompound(out);
    for (const TopoDS_Shape& s : kept) builder.Add(out, s);
    return out;
  }
  // The faces kept share their edges as the split left them: one shell, open along the cut.
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (const TopoDS_Shape& f : kept) builder.Add(shell, f);
  return shell;
}

}  // namespace semimesh::occ
