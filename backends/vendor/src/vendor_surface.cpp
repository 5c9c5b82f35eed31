#include "vendor_surface.hpp"

namespace semimesh::vendor {

VendorSurface::VendorSurface(int id, std::string name, int orientation, std::shared_ptr<const Connection> connection,
                             vc_entity face, cad::SurfaceKind kind, std::array<cad::Interval, 2> bounds,
                             std::array<std::optional<double>, 2> periods)
    : cad::Surface(id, std::move(name), orientation),
      connection_(std::move(connection)),
      face_(face),
      kind_(kind),
      bounds_(bounds),
      periods_(periods) {}

std::optional<double> VendorSurface::period(int direction) const {
  cad::Surface::period(direction);  // checks the direction
  return periods_[direction];
}

cad::SurfaceDerivatives VendorSurface::derivatives(const cad::Vec2& uv) const {
  cad::SurfaceDerivatives d;
  connection_->call("vc_face_eval", ref(), [&](vc_model m) {
    return vc_face_eval(m, face_, uv.data(), d.p.data(), d.du.data(), d.dv.data(), d.duu.data(), d.duv.data(),
                        d.dvv.data());
  });
  return d;
}

cad::Vec3 VendorSurface::point(const cad::Vec2& uv) const {
  cad::Vec3 p;
  connection_->call("vc_face_eval", ref(), [&](vc_model m) {
    return vc_face_eval(m, face_, uv.data(), p.data(), nullptr, nullptr, nullptr, nullptr, nullptr);
  });
  return p;
}

bool VendorSurface::contains(const cad::Vec2& uv) const {
  int inside = 0;
  connection_->call("vc_face_inside", ref(), [&](vc_model m) { return vc_face_inside(m, face_, uv.data(), &inside); });
  return inside != 0;
}

cad::SurfaceProjection VendorSurface::project(const cad::Vec3& x, std::optional<cad::Vec2> guess) const {
  cad::SurfaceProjection out;
  int converged = 0, inside = 0;
  connection_->call("vc_face_project", ref(), [&](vc_model m) {
    return vc_face_project(m, face_, x.data(), guess ? guess->data() : nullptr, out.uv.data(), out.point.data(),
                           &out.distance, &converged, &inside);
  });
  out.converged = converged != 0;
  out.inside = inside != 0;
  return out;
}

}  // namespace semimesh::vendor
