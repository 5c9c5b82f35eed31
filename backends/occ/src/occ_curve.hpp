// A cadapi Curve over the 3D curve of an OCC edge, restricted to the edge's parameter range; a
// degenerated edge (a pole, no 3D curve) is a degenerate curve at its vertex.
#pragma once

#include "semimesh/cad/curve.hpp"

#include <Geom_Curve.hxx>
#include <TopoDS_Edge.hxx>

#include <optional>
#include <vector>

namespace semimesh::occ {

class OccCurve final : public cad::Curve {
 public:
  /// `edge` in its FORWARD orientation; it must carry a 3D curve or be degenerated (throws
  /// CadError otherwise).
  OccCurve(int id, std::string name, const TopoDS_Edge& edge);

  cad::CurveKind kind() const override { return kind_; }
  cad::Interval bounds() const override { return range_; }
  cad::CurveDerivatives derivatives(double t) const override;
  /// Global search with GeomAPI_ProjectPointOnCurve on the edge range (ends included) without a
  /// guess, then the generic Newton polish; with a guess only the local Newton.
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess = std::nullopt) const override;
  bool is_degenerate() const override { return pole_.has_value(); }
  /// The curve's C1 intervals' ends inside the edge's range (GeomAdaptor_Curve::Intervals).
  const std::vector<double>& tangent_breaks() const override { return breaks_; }

  /// True when OCC evaluates this curve through a cached adaptor (offset curves).
  bool has_mutable_evaluator() const { return mutable_evaluator_; }

 private:
  Handle(Geom_Curve) curve_;  // null on a degenerate curve
  std::optional<cad::Vec3> pole_;  // the point of a degenerate curve
  cad::Interval range_;
  std::vector<double> breaks_;
  cad::CurveKind kind_ = cad::CurveKind::Other;
  bool mutable_evaluator_ = false;
};

}  // namespace semimesh::occ
