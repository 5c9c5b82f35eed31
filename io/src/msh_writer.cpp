#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/gmsh_types.hpp"
#include "semimesh/io/msh.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>

namespace semimesh::io {
namespace {

using Box = std::array<double, 6>;  // min x y z, max x y z

Box empty_box() {
  const double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, inf, -inf, -inf, -inf};
}

void grow(Box& box, const Eigen::Vector3d& x) {
  for (int k = 0; k < 3; ++k) {
    box[k] = std::min(box[k], x[k]);
    box[k + 3] = std::max(box[k + 3], x[k]);
  }
}

void write_element_line(AtomicFile& out, std::size_t tag, const std::vector<mesh::NodeId>& ids) {
  out.print("{}", tag);
  for (mesh::NodeId id : ids) out.print(" {}", id + 1);
  out.print("\n");
}

void write_physical_names(AtomicFile& out, const mesh::Mesh& m, bool has_volume) {
  const auto& groups = m.group_names();
  out.print("$PhysicalNames\n{}\n", groups.size() + (has_volume ? 1 : 0));
  for (std::size_t g = 0; g < groups.size(); ++g) out.print("2 {} \"{}\"\n", g + 1, groups[g]);
  if (has_volume) out.print("3 1 \"{}\"\n", kVolumeGroupName);
  out.print("$EndPhysicalNames\n");
}

/// Blocks of boundary faces keyed by (group, shape), in mesh order inside each block.
std::map<std::pair<int, ho::Shape>, std::vector<std::size_t>> boundary_blocks(const mesh::Mesh& m) {
  std::map<std::pair<int, ho::Shape>, std::vector<std::size_t>> blocks;
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    blocks[{m.boundary_faces()[b].group, m.boundary_faces()[b].shape}].push_back(b);
  return blocks;
}

std::map<ho::Shape, std::vector<std::size_t>> volume_blocks(const mesh::Mesh& m) {
  std::map<ho::Shape, std::vector<std::size_t>> blocks;
  for (std::size_t e = 0; e < m.elements().size(); ++e) blocks[m.elements()[e].shape].push_back(e);
  return blocks;
}

void write_v41(AtomicFile& out, const mesh::Mesh& m) {
  const bool has_volume = !m.elements().empty() || m.group_names().empty();
  const auto& groups = m.group_names();
  out.print("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  write_physical_names(out, m, has_volume);

  std::vector<Box> group_box(groups.size(), empty_box());
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    for (mesh::NodeId id : m.boundary_face_nodes(b)) grow(group_box[m.boundary_faces()[b].group], m.node(id));
  Box all = empty_box();
  for (const auto& x : m.nodes()) grow(all, x);
  if (m.nodes().empty()) all = {0, 0, 0, 0, 0, 0};
  out.print("$Entities\n0 0 {} {}\n", groups.size(), has_volume ? 1 : 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Box& b = group_box[g][0] <= group_box[g][3] ? group_box[g] : all;
    out.print("{} {} {} {} {} {} {} 1 {} 0\n", g + 1, b[0], b[1], b[2], b[3], b[4], b[5], g + 1);
  }
  if (has_volume) out.print("1 {} {} {} {} {} {} 1 1 0\n", all[0], all[1], all[2], all[3], all[4], all[5]);
  out.print("$EndEntities\n");

  // Every node goes in one block classified on the volume (or the first surface).
  const std::size_t n = m.num_nodes();
  out.print("$Nodes\n{} {} {} {}\n", n ? 1 : 0, n, n ? 1 : 0, n);
  if (n) {
    out.print("{} 1 0 {}\n", has_volume ? 3 : 2, n);
    for (std::size_t i = 1; i <= n; ++i) out.print("{}\n", i);
    for (const auto& x : m.nodes()) out.print("{} {} {}\n", x[0], x[1], x[2]);
  }
  out.print("$EndNodes\n");

  const auto volumes = volume_blocks(m);
  const auto boundaries = boundary_blocks(m);
  const std::size_t total = m.elements().size() + m.boundary_faces().size();
  out.print("$Elements\n{} {} {} {}\n", volumes.size() + boundaries.size(), total, total ? 1 : 0, total);
  std::size_t tag = 0;
  std::vector<mesh::NodeId> ids;
  for (const auto& [shape, list] : volumes) {
    out.print("3 1 {} {}\n", gmsh_element_type(shape, m.order()), list.size());
    for (std::size_t e : list) {
      m.element_nodes(e, ids);
      write_element_line(out, ++tag, ids);
    }
  }
  for (const auto& [key, list] : boundaries) {
    out.print("2 {} {} {}\n", key.first + 1, gmsh_element_type(key.second, m.order()), list.size());
    for (std::size_t b : list) write_element_line(out, ++tag, m.boundary_face_nodes(b));
  }
  out.print("$EndElements\n");
}

void write_v22(AtomicFile& out, const mesh::Mesh& m) {
  const bool has_volume = !m.elements().empty();
  out.print("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  write_physical_names(out, m, has_volume);
  out.print("$Nodes\n{}\n", m.num_nodes());
  std::size_t id = 0;
  for (const auto& x : m.nodes()) out.print("{} {} {} {}\n", ++id, x[0], x[1], x[2]);
  out.print("$EndNodes\n$Elements\n{}\n", m.elements().size() + m.boundary_faces().size());
  std::size_t tag = 0;
  std::vector<mesh::NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    out.print("{} {} 2 1 1", ++tag, gmsh_element_type(m.elements()[e].shape, m.order()));
    for (mesh::NodeId n : ids) out.print(" {}", n + 1);
    out.print("\n");
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    const auto& bf = m.boundary_faces()[b];
    out.print("{} {} 2 {} {}", ++tag, gmsh_element_type(bf.shape, m.order()), bf.group + 1, bf.group + 1);
    for (mesh::NodeId n : m.boundary_face_nodes(b)) out.print(" {}", n + 1);
    out.print("\n");
  }
  out.print("$EndElements\n");
}

}  // namespace

void write_msh(const mesh::Mesh& mesh, const std::string& path, MshVersion version) {
  gmsh_element_type(ho::Shape::Tetrahedron, mesh.order());  // rejects unsupported orders early
  std::optional<mesh::Mesh> resampled;
  if (mesh.node_set() != ho::NodeSet::Equispaced) resampled = to_equispaced(mesh);
  const mesh::Mesh& m = resampled ? *resampled : mesh;
  AtomicFile out(path);
  if (version == MshVersion::V41)
    write_v41(out, m);
  else
    write_v22(out, m);
  out.commit();
}

}  // namespace semimesh::io
