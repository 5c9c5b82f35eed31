#include "semimesh/io/pictures.hpp"

#include "semimesh/ho/basis.hpp"
#include "svg_canvas.hpp"

#include <limits>

namespace semimesh::io {

std::string svg_surface(const mesh::Mesh& mesh, const std::string& group, int axis, const std::string& title) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int first = std::min(u, v), second = std::max(u, v);
  const int samples = std::max(1, 2 * mesh.order());  // per edge: a curved edge is drawn curved
  std::vector<std::vector<Eigen::Vector2d>> outlines;
  std::array<double, 4> box = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& face = mesh.boundary_faces()[b];
    if (mesh.group_names()[face.group] != group) continue;
    const ho::LagrangeBasis basis(face.shape, mesh.order(), mesh.node_set());
    Eigen::MatrixX3d nodes(basis.size(), 3);
    const std::vector<mesh::NodeId> ids = mesh.boundary_face_nodes(b);
    for (int i = 0; i < basis.size(); ++i) nodes.row(i) = mesh.node(ids[i]).transpose();
    // The face's outline in reference coordinates: each edge between consecutive vertices.
    const Eigen::MatrixX3d corners = ho::reference_nodes(face.shape, 1);
    const int nv = static_cast<int>(corners.rows());
    Eigen::MatrixX3d outline(nv * samples, 3);
    for (int k = 0; k < nv; ++k)
      for (int s = 0; s < samples; ++s)
        outline.row(k * samples + s) = corners.row(k) + (corners.row((k + 1) % nv) - corners.row(k)) * s / samples;
    const Eigen::MatrixX3d x = ho::map_points(basis, nodes, outline);
    std::vector<Eigen::Vector2d> points;
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      points.emplace_back(x(i, first), x(i, second));
      box = {std::min(box[0], x(i, first)), std::min(box[1], x(i, second)), std::max(box[2], x(i, first)),
             std::max(box[3], x(i, second))};
    }
    outlines.push_back(std::move(points));
  }
  if (outlines.empty()) box = {0, 0, 1, 1};
  const double margin = 0.02 * std::max(box[2] - box[0], box[3] - box[1]);
  box = {box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin};
  detail::SvgCanvas canvas(box, 1000.0, title);
  for (const auto& points : outlines) {
    std::string path = "M" + canvas.at(points.front());
    for (std::size_t i = 1; i < points.size(); ++i) path += " L" + canvas.at(points[i]);
    canvas.draw("<path class=\"face\" d=\"" + path + " Z\" fill=\"#dde8f3\" stroke=\"#234\" stroke-width=\"0.4\"/>\n");
  }
  return canvas.svg();
}

}  // namespace semimesh::io
