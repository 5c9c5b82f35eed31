#include "semimesh/surface/size_field.hpp"

#include "semimesh/surface/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace semimesh::surface {
namespace {

using cad::Vec2;

constexpr int kLeafSize = 8;

void require(bool ok, const std::string& what) {
  if (!ok) throw SurfaceMeshError("size field: " + what);
}

double box_distance(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  return (x.cwiseMax(lo).cwiseMin(hi) - x).norm();
}

}  // namespace

const params::Table<SizeParams>& size_keys() {
  static const params::Table<SizeParams> table = {
      params::real("max_size", &SizeParams::max_size, "> 0", "largest edge length"),
      params::real("min_size", &SizeParams::min_size, "> 0", "smallest edge length (<= max_size)"),
      params::real("curvature_segments", &SizeParams::curvature_segments, ">= 0",
                   "segments per radian of turning; 0: no curvature sizing"),
      params::real("gradation", &SizeParams::gradation, ">= 1", "ratio limit between neighbouring edge lengths"),
      params::real("le_size", &SizeParams::le_size, ">= 0", "edge length along the curve named leading_edge; 0: off"),
      params::real("te_size", &SizeParams::te_size, ">= 0",
                   "edge length along trailing_edge / te_upper / te_lower; 0: off"),
  };
  return table;
}

std::vector<std::string> size_warnings(const SizeParams& params) {
  std::vector<std::string> out;
  const auto below = [&](const std::string& key, double size, const std::string& what) {
    if (size > 0.0 && size < params.min_size)
      out.push_back(key + " = " + params::to_text(size) + " is below sizing.min_size = " +
                    params::to_text(params.min_size) + ": the edges " + what + " get sizing.min_size");
  };
  below("sizing.le_size", params.le_size, "along the leading edge");
  below("sizing.te_size", params.te_size, "along the trailing edge");
  for (const CurveSource& src : params.curve_sources)
    below("the size of curve source '" + src.curve + "'", src.size, "along that curve");
  return out;
}

SizeField::SizeField(const cad::Model& model, const SizeParams& params) : SizeField(&model, params) {}

SizeField::SizeField(const SizeParams& params) : SizeField(nullptr, params) {}

SizeField::SizeField(const cad::Model* model, const SizeParams& params) : params_(params), slope_(params.gradation - 1.0) {
  if (const auto bad = params::violation(params, size_keys(), "sizing")) require(false, *bad);
  require(params.min_size <= params.max_size, "sizing.min_size = " + params::to_text(params.min_size) +
                                                  ": expected <= sizing.max_size = " + params::to_text(params.max_size));
  require(params.curvature_samples >= 2, "curvature_samples must be >= 2");

  auto by_name = [&](const std::string& name) -> const cad::Curve* {
    for (int c = 0; model && c < model->num_curves(); ++c)
      if (model->curve(c).name() == name) return &model->curve(c);
    return nullptr;
  };
  // LE/TE lists name the curves of the usual wing models; a name absent from this model is skipped
  // (a sharp TE has no te_upper), but an explicit curve source must exist.
  // Without a model (a mesh's sizes) only the point and box sources count.
  for (const auto& name : params.le_curves)
    if (const cad::Curve* c = params.le_size > 0.0 ? by_name(name) : nullptr) add_curve_samples(*c, params.le_size);
  for (const auto& name : params.te_curves)
    if (const cad::Curve* c = params.te_size > 0.0 ? by_name(name) : nullptr) add_curve_samples(*c, params.te_size);
  for (const auto& src : params.curve_sources) {
    if (!model) break;
    const cad::Curve* c = by_name(src.curve);
    require(c != nullptr, "curve source '" + src.curve + "' names no curve of the model");
    require(src.size > 0.0, "curve source '" + src.curve + "' needs a size > 0");
    add_curve_samples(*c, src.size);
  }
  for (const auto& p : params.point_sources) {
    require(p.size > 0.0, "point sources need a size > 0");
    add_source(p.center, p.size);
  }
  for (const auto& b : params.box_sources)
    require(b.size > 0.0 && (b.lo.array() <= b.hi.array()).all(), "box sources need size > 0 and lo <= hi");
  if (model && params.curvature_segments > 0.0) add_curvature_sources(*model);
  if (!sources_.empty()) build_tree(0, static_cast<int>(sources_.size()));
}

void SizeField::add_source(const Vec3& x, double size) {
  if (size < params_.max_size) sources_.push_back(PointSource{x, std::max(size, params_.min_size)});
}

void SizeField::add_curve_samples(const cad::Curve& curve, double size) {
  // Spacing <= size / 2 keeps the field within (1 + slope / 4) of `size` between samples.
  const cad::Interval range = curve.bounds();
  const double length = curve.length();
  const int n = std::max(1, static_cast<int>(std::ceil(2.0 * length / std::max(size, params_.min_size))));
  for (int i = 0; i <= n; ++i) add_source(curve.point(curve.parameter_at_length(range.lo, length * i / n)), size);
}

void SizeField::add_curvature_sources(const cad::Model& model) {
  const int n = params_.curvature_samples;
  const double segments = params_.curvature_segments;
  for (int c = 0; c < model.num_curves(); ++c) {
    const cad::Curve& curve = model.curve(c);
    const cad::Interval range = curve.bounds();
    for (int i = 0; i <= 2 * n; ++i) {
      const double t = range.lo + range.length() * i / (2 * n);
      const double kappa = curve.curvature(t);
      if (kappa > 0.0) add_source(curve.point(t), 1.0 / (kappa * segments));
    }
  }
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const cad::Surface& surface = model.surface(s);
    if (surface.is_planar()) continue;
    const auto box = surface.bounds();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const Vec2 uv(box[0].lo + box[0].length() * i / n, box[1].lo + box[1].length() * j / n);
        if (!surface.contains(uv)) continue;
        const cad::PrincipalCurvatures k = surface.curvatures(uv);
        const double kappa = std::max(std::abs(k.k_min), std::abs(k.k_max));
        if (kappa > 0.0) add_source(surface.point(uv), 1.0 / (kappa * segments));
      }
  }
}

int SizeField::build_tree(int begin, int end) {
  TreeNode node{Vec3::Constant(1e300), Vec3::Constant(-1e300), std::numeric_limits<double>::max(), begin, end, -1, -1};
  for (int i = begin; i < end; ++i) {
    node.lo = node.lo.cwiseMin(sources_[i].center);
    node.hi = node.hi.cwiseMax(sources_[i].center);
    node.min_size = std::min(node.min_size, sources_[i].size);
  }
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (end - begin > kLeafSize) {
    int axis;
    (node.hi - node.lo).maxCoeff(&axis);
    const int mid = (begin + end) / 2;
    std::nth_element(sources_.begin() + begin, sources_.begin() + mid, sources_.begin() + end,
                     [axis](const PointSource& a, const PointSource& b) { return a.center[axis] < b.center[axis]; });
    const int left = build_tree(begin, mid);
    const int right = build_tree(mid, end);
    nodes_[id].left = left;
    nodes_[id].right = right;
  }
  return id;
}

double SizeField::operator()(const Vec3& x) const {
  double best = params_.max_size;
  for (const auto& b : params_.box_sources) best = std::min(best, b.size + slope_ * box_distance(x, b.lo, b.hi));
  if (!nodes_.empty()) {
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const TreeNode& node = nodes_[stack[--top]];
      if (node.min_size + slope_ * box_distance(x, node.lo, node.hi) >= best) continue;
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i)
          best = std::min(best, sources_[i].size + slope_ * (x - sources_[i].center).norm());
      } else {
        // The nearer child first: its sources lower `best` before the farther one is looked at.
        const TreeNode& left = nodes_[node.left];
        const TreeNode& right = nodes_[node.right];
        const bool left_nearer = left.min_size + slope_ * box_distance(x, left.lo, left.hi) <=
                                 right.min_size + slope_ * box_distance(x, right.lo, right.hi);
        stack[top++] = left_nearer ? node.right : node.left;
        stack[top++] = left_nearer ? node.left : node.right;
      }
    }
  }
  return std::clamp(best, params_.min_size, params_.max_size);
}

}  // namespace semimesh::surface
