#include "occ_curve.hpp"
#include "to_vec.hpp"

#include "semimesh/cad/error.hpp"

#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp.hxx>
#include <TopoDS_Vertex.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace semimesh::occ {
namespace {

cad::CurveKind kind_of(GeomAbs_CurveType type) {
  switch (type) {
    case GeomAbs_Line: return cad::CurveKind::Line;
    case GeomAbs_Circle: return cad::CurveKind::Circle;
    case GeomAbs_Ellipse: return cad::CurveKind::Ellipse;
    case GeomAbs_BSplineCurve: return cad::CurveKind::BSpline;
    case GeomAbs_BezierCurve: return cad::CurveKind::Bezier;
    default: return cad::CurveKind::Other;
  }
}

}  // namespace

OccCurve::OccCurve(int id, std::string name, const TopoDS_Edge& edge) : cad::Curve(id, std::move(name)) {
  double first = 0.0, last = 0.0;
  if (BRep_Tool::Degenerated(edge)) {  // a pole: no 3D curve, its vertex stands for every t
    BRep_Tool::Range(edge, first, last);
    TopoDS_Vertex start, end;
    TopExp::Vertices(edge, start, end);
    pole_ = to_vec(BRep_Tool::Pnt(start).XYZ());
    range_ = {first, last};
    return;
  }
  curve_ = BRep_Tool::Curve(edge, first, last);  // location already applied
  if (curve_.IsNull())
    throw cad::CadError(cad::CadError::Kind::Geometry,
                        "occ: edge of curve " + std::to_string(id) + " has no 3D curve (try occ.heal = true)");
  range_ = {first, last};
  const GeomAdaptor_Curve adaptor(curve_);
  GeomAbs_CurveType type = adaptor.GetType();
  kind_ = kind_of(type);
  // A B-spline or Bezier curve caches its parametric resolution on first use, a write into the
  // shared curve when threads project onto it at once (GeomAPI_ProjectPointOnCurve asks for it):
  // filled here, before any thread sees the curve, every later use only reads it.
  try {
    adaptor.Resolution(1.0);
  } catch (const Standard_Failure&) {
    // no resolution for this curve: nothing cached to race on
  }
  mutable_evaluator_ = type == GeomAbs_OffsetCurve;
  const GeomAdaptor_Curve on_edge(curve_, first, last);
  if (const int pieces = on_edge.NbIntervals(GeomAbs_C1); pieces > 1) {
    TColStd_Array1OfReal ends(1, pieces + 1);
    on_edge.Intervals(ends, GeomAbs_C1);
    for (int i = 2; i <= pieces; ++i)
      if (ends(i) > first && ends(i) < last) breaks_.push_back(ends(i));
  }
}

cad::CurveDerivatives OccCurve::derivatives(double t) const {
  if (pole_) return {*pole_, cad::Vec3::Zero(), cad::Vec3::Zero()};
  gp_Pnt p;
  gp_Vec d1, d2;
  curve_->D2(t, p, d1, d2);
  return {to_vec(p.XYZ()), to_vec(d1.XYZ()), to_vec(d2.XYZ())};
}

cad::CurveProjection OccCurve::project(const cad::Vec3& x, std::optional<double> guess) const {
  if (pole_) {
    const double t = range_.clamp(guess.value_or(0.5 * (range_.lo + range_.hi)));
    return {t, *pole_, (x - *pole_).norm(), true};
  }
  if (guess) return cad::Curve::project(x, guess);
  // Extrema finds interior stationary points only; the edge ends compete with them.
  double best_t = range_.lo;
  double best = (point(range_.lo) - x).squaredNorm();
  if (double d = (point(range_.hi) - x).squaredNorm(); d < best) { best = d; best_t = range_.hi; }
  try {
    GeomAPI_ProjectPointOnCurve extrema(gp_Pnt(x.x(), x.y(), x.z()), curve_, range_.lo, range_.hi);
    if (extrema.NbPoints() > 0 && extrema.LowerDistance() * extrema.LowerDistance() < best)
      best_t = extrema.LowerDistanceParameter();
  } catch (const Standard_Failure&) {
    return cad::Curve::project(x);  // OCC gave up: the generic sampled start still works
  }
  return cad::Curve::project(x, best_t);
}

}  // namespace semimesh::occ
