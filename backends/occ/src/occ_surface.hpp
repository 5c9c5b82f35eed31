// A cadapi Surface over an OCC face: the face's geometric surface, its trimming (a 2D classifier
// on its wires, built once) and the orientation that makes normal() point into the fluid.
#pragma once

#include "semimesh/cad/surface.hpp"

#include <BRepTopAdaptor_FClass2d.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <memory>

namespace semimesh::occ {

class OccSurface final : public cad::Surface {
 public:
  /// `fluid_face`: the face oriented so that its OCC normal points into the fluid.
  OccSurface(int id, std::string name, const TopoDS_Face& fluid_face);

  cad::SurfaceKind kind() const override { return kind_; }
  std::array<cad::Interval, 2> bounds() const override { return bounds_; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override;
  bool contains(const cad::Vec2& uv) const override;
  /// Without a guess: every extremum GeomAPI_ProjectPointOnSurf finds on the face's parameter
  /// box, the nearest one inside the trimmed face preferred; then the generic Newton polish.
  /// With a guess: the local Newton only.
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<cad::Vec2> guess = std::nullopt) const override;

  /// True when OCC evaluates this surface through a cached adaptor (revolution, extrusion, offset).
  bool has_mutable_evaluator() const { return mutable_evaluator_; }

 private:
  TopoDS_Face face_;  // FORWARD, so that trimming is classified against the surface as stored
  Handle(Geom_Surface) surface_;
  std::array<cad::Interval, 2> bounds_;
  std::unique_ptr<BRepTopAdaptor_FClass2d> classifier_;
  cad::SurfaceKind kind_ = cad::SurfaceKind::Other;
  bool mutable_evaluator_ = false;
};

}  // namespace semimesh::occ
