#include "semimesh/io/equispaced.hpp"

#include "semimesh/ho/basis.hpp"

#include <map>

namespace semimesh::io {

mesh::Mesh to_equispaced(const mesh::Mesh& source) {
  mesh::Mesh out = source;
  if (source.node_set() == ho::NodeSet::Equispaced) return out;
  out.clear_cad_attachments();
  const int order = source.order();
  std::map<ho::Shape, Eigen::MatrixXd> resample;  // (n, n) per shape
  auto matrix = [&](ho::Shape shape) -> const Eigen::MatrixXd& {
    auto it = resample.find(shape);
    if (it == resample.end())
      it = resample
               .emplace(shape, ho::interpolation_matrix(ho::LagrangeBasis(shape, order, source.node_set()),
                                                        ho::LagrangeBasis(shape, order, ho::NodeSet::Equispaced)))
               .first;
    return it->second;
  };
  auto move_nodes = [&](ho::Shape shape, const std::vector<mesh::NodeId>& ids) {
    Eigen::MatrixX3d x(ids.size(), 3);
    for (std::size_t i = 0; i < ids.size(); ++i) x.row(i) = source.node(ids[i]).transpose();
    const Eigen::MatrixX3d y = matrix(shape) * x;
    for (std::size_t i = 0; i < ids.size(); ++i) out.place_node(ids[i], y.row(i).transpose());
  };
  std::vector<mesh::NodeId> ids;
  for (std::size_t b = 0; b < source.boundary_faces().size(); ++b)
    move_nodes(source.boundary_faces()[b].shape, source.boundary_face_nodes(b));
  for (std::size_t e = 0; e < source.elements().size(); ++e) {
    source.element_nodes(e, ids);
    move_nodes(source.elements()[e].shape, ids);
  }
  out.relabel_node_set(ho::NodeSet::Equispaced);
  return out;
}

}  // namespace semimesh::io
