// A cad::Surface answered by the vendor kernel's vc_face_* calls.
#pragma once

#include "connection.hpp"

#include "semimesh/cad/surface.hpp"

#include <memory>

namespace semimesh::vendor {

class VendorSurface final : public cad::Surface {
 public:
  /// `orientation` is +1 when the face's natural normal points into the fluid (vendor sense SAME).
  VendorSurface(int id, std::string name, int orientation, std::shared_ptr<const Connection> connection,
                vc_entity face, cad::SurfaceKind kind, std::array<cad::Interval, 2> bounds,
                std::array<std::optional<double>, 2> periods);

  cad::SurfaceKind kind() const override { return kind_; }
  std::array<cad::Interval, 2> bounds() const override { return bounds_; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override;
  cad::Vec3 point(const cad::Vec2& uv) const override;
  bool contains(const cad::Vec2& uv) const override;
  std::optional<double> period(int direction) const override;
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<cad::Vec2> guess = std::nullopt) const override;

 private:
  EntityRef ref() const { return {"face", face_, id(), &name()}; }

  std::shared_ptr<const Connection> connection_;
  vc_entity face_;
  cad::SurfaceKind kind_;
  std::array<cad::Interval, 2> bounds_;  // cached: asked for by every projection
  std::array<std::optional<double>, 2> periods_;  // read once at load
};

}  // namespace semimesh::vendor
