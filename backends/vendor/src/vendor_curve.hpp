// A cad::Curve answered by the vendor kernel's vc_edge_* calls.
#pragma once

#include "connection.hpp"

#include "semimesh/cad/curve.hpp"

#include <memory>

namespace semimesh::vendor {

class VendorCurve final : public cad::Curve {
 public:
  VendorCurve(int id, std::string name, std::shared_ptr<const Connection> connection, vc_entity edge,
              cad::CurveKind kind, cad::Interval bounds, bool degenerate);

  cad::CurveKind kind() const override { return kind_; }
  cad::Interval bounds() const override { return bounds_; }
  cad::CurveDerivatives derivatives(double t) const override;
  cad::Vec3 point(double t) const override;
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess = std::nullopt) const override;
  bool is_degenerate() const override { return degenerate_; }

 private:
  EntityRef ref() const { return {"edge", edge_, id(), &name()}; }

  std::shared_ptr<const Connection> connection_;
  vc_entity edge_;
  cad::CurveKind kind_;
  cad::Interval bounds_;  // cached: asked for on every sweep of the curve
  bool degenerate_;
};

}  // namespace semimesh::vendor
