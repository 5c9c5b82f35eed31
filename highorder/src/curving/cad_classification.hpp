// Which CAD entity a mesh edge or face lies on, from the CAD attachments of its vertices, and the
// parameters of its vertices on that entity.
//  - An edge lies on curve c when both vertices are on c: attached to c, or to a CAD vertex that c
//    starts or ends at.
//  - Otherwise an edge or face lies on surface s when every vertex is on s: attached to s, to a
//    curve bounding s, or to a CAD vertex of such a curve. When several surfaces qualify (a single
//    element spanning a whole face), the one closest to `probe` wins.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace semimesh::ho::detail {

struct CadPlace {
  enum Kind { None, Curve, Surface };
  Kind kind = None;
  int id = -1;
};

CadPlace classify(const cad::Model& model, const std::vector<mesh::CadAttachment>& vertices, bool allow_curve,
                  const cad::Vec3& probe);

/// Parameter on `curve` of a node at x with attachment `a`: its own parameter when attached to the
/// curve, the curve's end for a CAD vertex (of a closed curve, whose vertex is both ends: the end
/// nearer `other_end`, the parameter of the edge's other node, so the edge does not run round the
/// whole curve; the start when not given), else the projection.
double curve_parameter(const cad::Model& model, int curve, const mesh::CadAttachment& a, const cad::Vec3& x,
                       std::optional<double> other_end);

/// (u, v) on `surface` of a node at x with attachment `a`: its own when attached to the surface,
/// else the projection of x (seeded by `guess` when given).
cad::Vec2 surface_parameter(const cad::Model& model, int surface, const mesh::CadAttachment& a, const cad::Vec3& x,
                            const cad::Vec2* guess = nullptr);

/// Makes rows [0, count) of `uv` (an element's nodes on `surface`, vertices first) one continuous
/// patch of the surface's parameters: across a periodic seam each row moves by whole periods next
/// to the first vertex that is not at a pole; a vertex at a pole (where the surface does not move
/// along one parameter) takes along that parameter the mean of the other vertices, the parameter
/// its fan reaches it with. `vertices`: how many of the rows are the element's vertices.
void continuous_parameters(const cad::Surface& surface, Eigen::Ref<Eigen::MatrixXd> uv, int count, int vertices);

/// uv moved by whole periods into the surface's parameter box where it is periodic.
cad::Vec2 into_box(const cad::Surface& surface, cad::Vec2 uv);

}  // namespace semimesh::ho::detail
