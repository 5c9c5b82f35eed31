// 1D meshes of CAD curves. Each curve is meshed once; every surface it bounds takes its nodes from
// that one mesh, so neighbouring surface meshes share exactly the same boundary points.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/surface/size_field.hpp"

#include <map>
#include <vector>

namespace semimesh::surface {

/// Nodes of one curve, in increasing parameter: t.front() == bounds().lo, t.back() == bounds().hi
/// exactly; points[i] == curve.point(t[i]), except the two ends, which are the model's end vertex
/// points (so curves meeting at a vertex share the very same point).
struct CurveMesh {
  int curve = -1;
  std::vector<double> t;       ///< [n + 1]
  std::vector<Vec3> points;    ///< [n + 1]
  int segments() const { return static_cast<int>(t.size()) - 1; }
};

/// Distribution of a prescribed number of segments along the arc length.
struct Bunching {
  enum class Law {
    Uniform,    ///< equal lengths
    Geometric,  ///< each segment `parameter` times the previous one (from the curve's start)
    Tanh,       ///< two-sided tanh clustering toward both ends; `parameter` = strength (> 0)
    Cosine,     ///< two-sided cosine (Chebyshev-like) clustering toward both ends
  };
  Law law = Law::Uniform;
  double parameter = 1.0;
};

/// A user-fixed discretisation of one curve.
struct CurveCount {
  int segments = 1;
  Bunching bunching;
};

/// Size-driven: n = max(min_segments, round(integral of ds / h)) segments (at least 3 on a closed
/// curve), nodes placed by arc length so that each segment holds an equal share of the integral.
/// A degenerate curve (a pole) gets one segment whatever the size or count: both its nodes are its
/// vertex. Throws SurfaceMeshError on an unknown curve id or min_segments < 1.
CurveMesh discretise_curve(const cad::Model& model, int curve, const SizeField& size, int min_segments = 1);

/// Size-graded as above, but exactly `segments` segments (the nodes at equal shares of the integral
/// of ds / h). Throws SurfaceMeshError on segments < 1 (< 3 on a closed curve).
CurveMesh discretise_curve_to_count(const cad::Model& model, int curve, const SizeField& size, int segments);

/// Prescribed count with a bunching law (fractions of the arc length). Throws SurfaceMeshError on
/// segments < 1 or an invalid bunching parameter.
CurveMesh discretise_curve(const cad::Model& model, int curve, const CurveCount& count);

/// The curve meshes of a whole model, indexed by curve id.
class CurveMeshes {
 public:
  CurveMeshes() = default;
  explicit CurveMeshes(std::vector<CurveMesh> meshes);
  /// Throws SurfaceMeshError when the curve has no mesh.
  const CurveMesh& at(int curve) const;
  int size() const { return static_cast<int>(meshes_.size()); }
  const std::vector<CurveMesh>& all() const { return meshes_; }

 private:
  std::vector<CurveMesh> meshes_;
};

/// Meshes every curve of the model: by `counts` where given (keyed by curve id), by size otherwise.
CurveMeshes discretise_all_curves(const cad::Model& model, const SizeField& size,
                                  const std::map<int, CurveCount>& counts = {}, int min_segments = 1);

}  // namespace semimesh::surface
