#include "vendor_curve.hpp"

namespace semimesh::vendor {

VendorCurve::VendorCurve(int id, std::string name, std::shared_ptr<const Connection> connection, vc_entity edge,
                         cad::CurveKind kind, cad::Interval bounds, bool degenerate)
    : cad::Curve(id, std::move(name)),
      connection_(std::move(connection)),
      edge_(edge),
      kind_(kind),
      bounds_(bounds),
      degenerate_(degenerate) {}

cad::CurveDerivatives VendorCurve::derivatives(double t) const {
  cad::CurveDerivatives d;
  connection_->call("vc_edge_eval", ref(),
                    [&](vc_model m) { return vc_edge_eval(m, edge_, t, d.p.data(), d.d1.data(), d.d2.data()); });
  return d;
}

cad::Vec3 VendorCurve::point(double t) const {
  cad::Vec3 p;
  connection_->call("vc_edge_eval", ref(), [&](vc_model m) { return vc_edge_eval(m, edge_, t, p.data(), nullptr, nullptr); });
  return p;
}

cad::CurveProjection VendorCurve::project(const cad::Vec3& x, std::optional<double> guess) const {
  cad::CurveProjection out;
  int converged = 0;
  connection_->call("vc_edge_project", ref(), [&](vc_model m) {
    return vc_edge_project(m, edge_, x.data(), guess ? &*guess : nullptr, &out.t, out.point.data(), &out.distance,
                           &converged);
  });
  out.converged = converged != 0;
  return out;
}

}  // namespace semimesh::vendor
