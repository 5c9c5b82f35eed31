#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <optional>

namespace semimesh::io {

void write_vtu(const mesh::Mesh& mesh, const std::string& path) {
  std::optional<mesh::Mesh> resampled;
  if (mesh.node_set() != ho::NodeSet::Equispaced) resampled = to_equispaced(mesh);
  const mesh::Mesh& m = resampled ? *resampled : mesh;
  const std::size_t num_cells = m.elements().size() + m.boundary_faces().size();

  AtomicFile out(path);
  out.print("<?xml version=\"1.0\"?>\n");
  out.print("<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n<UnstructuredGrid>\n");
  out.print("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", m.num_nodes(), num_cells);
  out.print("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const auto& x : m.nodes()) out.print("{} {} {}\n", x[0], x[1], x[2]);
  out.print("</DataArray>\n</Points>\n<Cells>\n");

  std::vector<mesh::NodeId> ids;
  std::vector<std::size_t> offsets;
  offsets.reserve(num_cells);
  std::size_t offset = 0;
  auto write_cell = [&](ho::Shape shape, const std::vector<mesh::NodeId>& canonical) {
    const auto& perm = vtk_from_canonical(shape, m.order());
    for (std::size_t i = 0; i < perm.size(); ++i) out.print(i ? " {}" : "{}", canonical[perm[i]]);
    out.print("\n");
    offset += perm.size();
    offsets.push_back(offset);
  };
  out.print("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    write_cell(m.elements()[e].shape, ids);
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    write_cell(m.boundary_faces()[b].shape, m.boundary_face_nodes(b));
  out.print("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (std::size_t o : offsets) out.print("{}\n", o);
  out.print("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (const auto& el : m.elements()) out.print("{}\n", vtk_cell_type(el.shape));
  for (const auto& bf : m.boundary_faces()) out.print("{}\n", vtk_cell_type(bf.shape));
  out.print("</DataArray>\n</Cells>\n<CellData>\n");
  out.print("<DataArray type=\"Int32\" Name=\"boundary_group\" format=\"ascii\">\n");
  for (std::size_t e = 0; e < m.elements().size(); ++e) out.print("-1\n");
  for (const auto& bf : m.boundary_faces()) out.print("{}\n", bf.group);
  out.print("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  out.commit();
}

}  // namespace semimesh::io
