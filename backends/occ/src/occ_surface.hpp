// A cadapi Surface over an OCC face: the face's geometric surface, its trimming (a 2D classifier
// on its wires, built once) and the orientation that makes normal() point into the fluid.
#pragma once

#include "sample_grid.hpp"
#include "semimesh/cad/surface.hpp"
#include "trim_raster.hpp"

#include <BRepTopAdaptor_FClass2d.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace semimesh::occ {

class OccSurface final : public cad::Surface {
 public:
  /// `fluid_face`: the face oriented so that its OCC normal points into the fluid.
  OccSurface(int id, std::string name, const TopoDS_Face& fluid_face);

  cad::SurfaceKind kind() const override { return kind_; }
  /// A plane, or any surface (B-spline, offset, ...) whose face lies in a plane to within 1e-7 of
  /// the face's size (GeomLib_IsPlanarSurface on its parameter box): CAD tools export planar walls
  /// and box faces as B-splines.
  bool is_planar() const override { return planar_; }
  std::array<cad::Interval, 2> bounds() const override { return bounds_; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override;
  bool contains(const cad::Vec2& uv) const override;
  /// Without a guess: Newton from the few nearest local minima of the sample grid; when none of
  /// them lands inside the trimmed face, also from every extremum GeomAPI_ProjectPointOnSurf
  /// finds. The nearest converged result inside the face wins, else the nearest one. Here a
  /// foot within the face's boundary tolerance counts as inside (within_tolerance_of_face).
  /// With a guess: the local Newton only.
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<cad::Vec2> guess = std::nullopt) const override;
  /// The guided project()'s local Newton without its contains() (cad::Surface::local_projection).
  cad::SurfaceProjection project_near(const cad::Vec3& x, const cad::Vec2& guess) const override {
    return local_projection(x, guess);
  }

  /// OCC's period of a periodic parameter; for a closed, non-periodic one (a closed B-spline) the
  /// length of the surface's parameter range, over which it closes on itself.
  std::optional<double> period(int direction) const override;
  /// BRepGProp::SurfaceProperties over the trimmed face (Gauss integration on the face's domain).
  std::optional<double> exact_area() const override;

  /// True when OCC evaluates this surface through an evaluator it may cache in (revolution,
  /// extrusion, offset): each thread then evaluates its own copy (thread_copy), so threads may
  /// share the surface all the same.
  bool has_mutable_evaluator() const { return mutable_evaluator_; }
  /// derivatives() straight from the face's own surface, never a thread's copy nor span cache: the
  /// reference a single thread gets (tests pin derivatives() of a copy to it, bit for bit).
  cad::SurfaceDerivatives derivatives_shared(const cad::Vec2& uv) const;

  /// contains() without the trim raster: OCC's classifier alone (the slow reference it is tested
  /// against).
  bool contains_exactly(const cad::Vec2& uv) const;
  /// The raster that answers most of contains() and of the tolerant test (built on first use);
  /// null when the face's loops could not be sampled finely enough (then every query is exact).
  const TrimRaster* trim_raster() const;

 private:
  static constexpr int kGridSeeds = 3;  // local minima of the grid polished by Newton per query

  /// Classified with a parameter tolerance covering how far the wires' pcurves stray from their
  /// edges' 3D curves: STEP files may hold pcurves less accurate than the edge tolerance claims,
  /// and the exact foot of a point of such an edge must count as inside.
  bool within_tolerance_of_face(const cad::Vec2& uv) const;
  /// This thread's classifier of the face (built on first use) with the face's tolerance
  /// (contains()) or, `tolerant`, the boundary tolerance (project()). OCC's const Perform writes the
  /// "current item" of its sequences of wires, so threads classifying on one classifier at once read
  /// another wire's polygon or walk off the sequence (a SIGSEGV): each thread has its own.
  BRepTopAdaptor_FClass2d& thread_classifier(bool tolerant) const;
  /// The surface this thread evaluates: its own copy when the evaluator may cache, else the face's.
  const Handle(Geom_Surface)& evaluated_surface() const;
  /// Starts from OCC's extrema: the nearest inside the trimmed face, then the nearest overall.
  std::vector<cad::Vec2> extremum_starts(const cad::Vec3& x) const;

  TopoDS_Face face_;  // FORWARD, so that trimming is classified against the surface as stored
  Handle(Geom_Surface) surface_;
  std::array<cad::Interval, 2> bounds_;
  std::unique_ptr<SampleGrid> grid_;  // built once after surface_ and bounds_
  double uv_tolerance_ = 0.0;           // of the tolerant classifier
  mutable std::once_flag raster_built_;
  mutable std::unique_ptr<TrimRaster> raster_;
  cad::SurfaceKind kind_ = cad::SurfaceKind::Other;
  std::array<std::optional<double>, 2> periods_;  // period(), found once
  bool planar_ = false;
  bool mutable_evaluator_ = false;
  bool span_cached_ = false;  // B-spline or Bezier: evaluated through this thread's span cache
  std::uint64_t serial_ = 0;  // keys this thread's adaptor, copy and classifiers of the face
};

}  // namespace semimesh::occ
