// VTK XML UnstructuredGrid (.vtu) with VTK Lagrange cells (see vtk_order.hpp) for ParaView.
// Header version="2.2" so readers use the VTK >= 9.1 hexahedron numbering.
// Points: every mesh node (point i = NodeId i), equispaced. Cells: volume elements, then boundary
// faces. Cell data "boundary_group": -1 for volume cells, else the index i of
// Mesh::group_names()[i]; "region": the volume region id of a volume cell (names in a comment), -1
// for boundary faces.
// Encodings: CompressedBinary (ParaView's own default): every array appended as raw binary,
// zlib-compressed in 64 KiB blocks (compressor="vtkZLibDataCompressor", header_type UInt64),
// written block by block as compressed; or ASCII (every reader, much larger). Points are Float64;
// connectivity and offsets Int32 (Int64 only when a value could overflow it). Pyramids are linear VTK_PYRAMID cells (VTK 9.1 has no
// Lagrange pyramid): their curvature is not shown.
#pragma once

#include "semimesh/io/equispaced.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <string>

namespace semimesh::io {

enum class VtuEncoding { CompressedBinary, Ascii };

/// Writes atomically; throws std::runtime_error for I/O failures.
void write_vtu(const mesh::Mesh& mesh, const std::string& path, VtuEncoding encoding = VtuEncoding::CompressedBinary);
/// The same with the equispaced node positions given (computed once for several formats).
void write_vtu(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
               VtuEncoding encoding = VtuEncoding::CompressedBinary);

}  // namespace semimesh::io
