// Target edge length h(x) at a 3D point, shared by the curve and the surface meshers.
//
//   h(x) = clamp( min( max_size, min_i [ h_i + (gradation - 1) |x - x_i| ] ), min_size, max_size )
//
// over point sources (x_i, h_i). Sources come from
//  - curvature: curves and surfaces are sampled; where the radius of curvature R = 1/kappa is
//    small, a source of size R / curvature_segments is added (kappa: curve curvature, or the
//    largest absolute principal curvature of a surface), i.e. `curvature_segments` segments per
//    radian of turning;
//  - user point sources and box sources (a box counts as distance 0 inside it);
//  - curve sources (LE/TE clustering): a curve named in `le_curves` / `te_curves` (or listed in
//    `curve_sources`) gets the given size along its whole length, sampled densely enough that
//    the field does not bulge between samples. Names in le_curves / te_curves that the model
//    lacks are skipped (a sharp TE has no te_upper); a name in curve_sources must exist.
// The term (gradation - 1) |x - x_i| bounds the growth: two neighbouring edges differ in length by
// at most the ratio `gradation` (e.g. 1.2), on curves and surfaces alike.
#pragma once

#include "semimesh/params/table.hpp"
#include "semimesh/cad/model.hpp"

#include <string>
#include <vector>

namespace semimesh::surface {

using cad::Vec3;

/// A size at a point.
struct PointSource {
  Vec3 center = Vec3::Zero();
  double size = 0.0;
};

/// A size inside an axis-aligned box.
struct BoxSource {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  double size = 0.0;
};

/// A size along a named curve of the model.
struct CurveSource {
  std::string curve;
  double size = 0.0;
};

/// The keys a user sets (ranges, meanings): size_keys(), the config's [sizing] section; besides
/// them min_size <= max_size.
struct SizeParams {
  double max_size = 2.0;
  double min_size = 0.005;
  double curvature_segments = 4.0;
  double gradation = 1.2;
  double le_size = 0.02;             ///< size along the `le_curves`; 0: none
  double te_size = 0.01;             ///< size along the `te_curves`; 0: none
  std::vector<std::string> le_curves = {"leading_edge"};
  std::vector<std::string> te_curves = {"trailing_edge", "te_upper", "te_lower"};
  std::vector<PointSource> point_sources;
  std::vector<BoxSource> box_sources;
  std::vector<CurveSource> curve_sources;
  int curvature_samples = 48;        ///< samples per curve and per surface direction for curvature
};

/// One row per user key of SizeParams (semimesh/params/table.hpp).
const params::Table<SizeParams>& size_keys();

/// A sentence per size the field cannot give because min_size bounds it (le_size, te_size or a
/// curve source below min_size: those edges get min_size), naming both keys; empty if none.
std::vector<std::string> size_warnings(const SizeParams& params);

class SizeField {
 public:
  /// Samples the model once. Throws SurfaceMeshError naming the parameter when one is out of range
  /// or a source curve name does not exist in the model.
  SizeField(const cad::Model& model, const SizeParams& params);
  /// A field of the params' point and box sources alone, for sizes that come from a mesh rather
  /// than a model (the far field's interior points): no curve or curvature sources.
  explicit SizeField(const SizeParams& params);

  /// Target edge length at x.
  double operator()(const Vec3& x) const;

  const SizeParams& params() const { return params_; }
  /// Number of point sources (for reports).
  int num_sources() const { return static_cast<int>(sources_.size()); }

 private:
  SizeField(const cad::Model* model, const SizeParams& params);

  // A bounding-box tree over the sources: a query skips every box whose smallest size plus the
  // graded distance to the box cannot beat the best size found so far.
  struct TreeNode {
    Vec3 lo, hi;
    double min_size;
    int begin, end;       // range of sources_
    int left, right;      // children, -1 for a leaf
  };

  void add_source(const Vec3& x, double size);
  void add_curve_samples(const cad::Curve& curve, double size);
  void add_curvature_sources(const cad::Model& model);
  int build_tree(int begin, int end);

  SizeParams params_;
  double slope_;                       // gradation - 1
  std::vector<PointSource> sources_;   // [sources], reordered into tree order
  std::vector<TreeNode> nodes_;        // [nodes], root first
};

}  // namespace semimesh::surface
