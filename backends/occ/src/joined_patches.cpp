#include "joined_patches.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <optional>

namespace semimesh::occ {
namespace {

using Patch = Handle(Geom_BSplineSurface);

// The face's surface with the face's normal when the face has natural bounds (an untrimmed patch).
std::optional<Patch> untrimmed_patch(const TopoDS_Face& face) {
  TopLoc_Location location;
  const Patch surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face, location));
  if (surface.IsNull()) return std::nullopt;
  Patch patch = Handle(Geom_BSplineSurface)::DownCast(surface->Transformed(location.Transformation()));
  double u0, u1, v0, v1, su0, su1, sv0, sv1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  patch->Bounds(su0, su1, sv0, sv1);
  const double eps = 1e-9 * (1.0 + std::abs(su1 - su0) + std::abs(sv1 - sv0));
  if (std::abs(u0 - su0) > eps || std::abs(u1 - su1) > eps || std::abs(v0 - sv0) > eps || std::abs(v1 - sv1) > eps)
    return std::nullopt;
  if (face.Orientation() == TopAbs_REVERSED) patch->UReverse();  // the face's normal is the surface's
  return patch;
}

// The rotation `quarter` (0..3) of the patch's parameter square: the sides go round, the normal
// stays (a swap of u and v, or one reversal, would flip it).
Patch rotated(const Patch& patch, int quarter) {
  Patch p = Handle(Geom_BSplineSurface)::DownCast(patch->Copy());
  for (int q = 0; q < quarter; ++q) {  // (u, v) -> (v, -u)... a quarter turn: swap, then reverse one
    p->ExchangeUV();
    p->UReverse();
  }
  return p;
}

// Knots mapped affinely onto [0, 1] (a patch's own parameter range does not matter).
std::vector<double> unit_knots(const TColStd_Array1OfReal& knots) {
  std::vector<double> out;
  const double lo = knots.First(), span = knots.Last() - knots.First();
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) out.push_back((knots(i) - lo) / span);
  return out;
}

bool same_knots_across(const Patch& a, const Patch& b) {  // along v, the shared side's direction
  if (a->VDegree() != b->VDegree() || a->UDegree() != b->UDegree() || a->NbVKnots() != b->NbVKnots()) return false;
  const std::vector<double> ka = unit_knots(a->VKnots()), kb = unit_knots(b->VKnots());
  for (std::size_t i = 0; i < ka.size(); ++i)
    if (std::abs(ka[i] - kb[i]) > 1e-9 || a->VMultiplicity(static_cast<int>(i) + 1) != b->VMultiplicity(static_cast<int>(i) + 1))
      return false;
  return true;
}

// A's last row of control points (u max) against B's first (u min), weights too; a side shrunk
// to a point (a fuselage's nose) is shared by every patch round it and joins none.
bool same_side(const Patch& a, const Patch& b, double tolerance) {
  const int last = a->NbUPoles();
  if (a->Pole(last, 1).Distance(a->Pole(last, a->NbVPoles())) <= tolerance &&
      a->Pole(last, 1).Distance(a->Pole(last, 1 + a->NbVPoles() / 2)) <= tolerance)
    return false;
  for (int j = 1; j <= a->NbVPoles(); ++j) {
    if (a->Pole(last, j).Distance(b->Pole(1, j)) > tolerance) return false;
    if (std::abs(a->Weight(last, j) - b->Weight(1, j)) > 1e-12 * a->Weight(last, j)) return false;
  }
  return true;
}

// Their normals agree along the side (a smooth skin, not a crease): checked at a few points.
bool smooth_across(const Patch& a, const Patch& b) {
  constexpr int kSamples = 9;
  constexpr double kCosOneDegree = 0.99985;
  double au0, au1, av0, av1, bu0, bu1, bv0, bv1;
  a->Bounds(au0, au1, av0, av1);
  b->Bounds(bu0, bu1, bv0, bv1);
  for (int k = 0; k <= kSamples; ++k) {
    const double f = static_cast<double>(k) / kSamples;
    GeomLProp_SLProps pa(a, au1, av0 + f * (av1 - av0), 1, Precision::Confusion());
    GeomLProp_SLProps pb(b, bu0, bv0 + f * (bv1 - bv0), 1, Precision::Confusion());
    if (!pa.IsNormalDefined() || !pb.IsNormalDefined()) continue;  // a pole (a nose's point)
    if (pa.Normal().Dot(pb.Normal()) < kCosOneDegree) return false;
  }
  return true;
}

// A then B along u, one surface: B's knots follow A's, the joint a knot of multiplicity degree.
Patch concatenated(const Patch& a, const Patch& b) {
  const int na = a->NbUPoles(), nb = b->NbUPoles(), nv = a->NbVPoles(), degree = a->UDegree();
  TColgp_Array2OfPnt poles(1, na + nb - 1, 1, nv);
  TColStd_Array2OfReal weights(1, na + nb - 1, 1, nv);
  for (int i = 1; i <= na; ++i)
    for (int j = 1; j <= nv; ++j) poles(i, j) = a->Pole(i, j), weights(i, j) = a->Weight(i, j);
  for (int i = 2; i <= nb; ++i)
    for (int j = 1; j <= nv; ++j) poles(na + i - 1, j) = b->Pole(i, j), weights(na + i - 1, j) = b->Weight(i, j);
  const int ka = a->NbUKnots(), kb = b->NbUKnots();
  TColStd_Array1OfReal knots(1, ka + kb - 1);
  TColStd_Array1OfInteger mults(1, ka + kb - 1);
  for (int i = 1; i <= ka; ++i) knots(i) = a->UKnot(i), mults(i) = a->UMultiplicity(i);
  mults(ka) = degree;
  const double shift = a->UKnot(ka) - b->UKnot(1);
  for (int i = 2; i <= kb; ++i) knots(ka + i - 1) = b->UKnot(i) + shift, mults(ka + i - 1) = b->UMultiplicity(i);
  TColStd_Array1OfReal vknots(1, a->NbVKnots());
  TColStd_Array1OfInteger vmults(1, a->NbVKnots());
  a->VKnots(vknots);
  a->VMultiplicities(vmults);
  return new Geom_BSplineSurface(poles, weights, knots, vknots, mults, vmults, degree, a->VDegree());
}

// Whether the patch's first and last rows of control points (along u) coincide: a ring.
bool closed(const Patch& patch, double tolerance) {
  for (int j = 1; j <= patch->NbVPoles(); ++j)
    if (patch->Pole(1, j).Distance(patch->Pole(patch->NbUPoles(), j)) > tolerance) return false;
  return true;
}

// A and B as one patch when they meet side to side.
std::optional<Patch> joined(const Patch& a, const Patch& b, double tolerance) {
  for (int qa = 0; qa < 4; ++qa) {
    const Patch ra = rotated(a, qa);
    for (int qb = 0; qb < 4; ++qb) {
      const Patch rb = rotated(b, qb);
      if (same_knots_across(ra, rb) && same_side(ra, rb, tolerance) && smooth_across(ra, rb))
        return concatenated(ra, rb);
    }
  }
  return std::nullopt;
}

}  // namespace

TopoDS_Shape with_patches_joined(const TopoDS_Shell& faces, double tolerance, std::vector<std::string>& repairs) {
  std::vector<Patch> patches;
  std::vector<TopoDS_Face> kept;
  for (TopExp_Explorer f(faces, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face face = TopoDS::Face(f.Current());
    if (const auto patch = untrimmed_patch(face)) patches.push_back(*patch);
    else kept.push_back(face);
  }
  const std::size_t before = patches.size();
  // A ring closed early (a section's quadrants round) would begin where its neighbour ring does
  // not, and the two would not join: closing joins wait until no other is left.
  for (bool closing : {false, true})
    for (bool merged = true; merged;) {
      merged = false;
      for (std::size_t i = 0; i < patches.size() && !merged; ++i)
        for (std::size_t j = i + 1; j < patches.size() && !merged; ++j)
          if (const auto both = joined(patches[i], patches[j], tolerance); both && (closing || !closed(*both, tolerance))) {
            patches[i] = *both;
            patches.erase(patches.begin() + static_cast<std::ptrdiff_t>(j));
            merged = true;
          }
    }
  if (patches.size() == before) return faces;
  BRepBuilderAPI_Sewing sewing(tolerance);
  for (const Patch& patch : patches) sewing.Add(BRepBuilderAPI_MakeFace(patch, Precision::Confusion()).Face());
  for (const TopoDS_Face& face : kept) sewing.Add(face);
  sewing.Perform();
  repairs.push_back("joined " + std::to_string(before) + " patches of the wall part into " +
                    std::to_string(patches.size()) + " face(s) (untrimmed B-spline patches meeting side to side, "
                    "their control points kept: the wall layer stands on one face)");
  return sewing.SewedShape();
}

}  // namespace semimesh::occ
