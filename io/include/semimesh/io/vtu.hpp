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
#include "semimesh/progress.hpp"

#include <string>

namespace semimesh::io {

enum class VtuEncoding { CompressedBinary, Ascii };

/// Writes atomically; throws std::runtime_error for I/O failures. `progress`: per data array
/// (compressed encoding only).
void write_vtu(const mesh::Mesh& mesh, const std::string& path, VtuEncoding encoding = VtuEncoding::CompressedBinary,
               const ProgressCallback& progress = {});
/// The same with the equispaced node positions given (computed once for several formats).
void write_vtu(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
               VtuEncoding encoding = VtuEncoding::CompressedBinary, const ProgressCallback& progress = {});

/// A ParaView multiblock data set (.vtm, VTK's XML vtkMultiBlockDataSet) for opening and slicing
/// without a threshold: block "volume" (the volume elements with every node, cell data "region")
/// and one block per boundary group, named after it and in group order (its faces with only the
/// nodes they use, cell data "boundary_group"). Each block is a compressed .vtu as above, in the
/// folder beside `path` named like it without the extension (ParaView's own layout):
/// `NAME.vtm`, `NAME/volume.vtu`, `NAME/boundary<i>_<group>.vtu`. Atomic for the pair: the pieces
/// are written in a temporary folder that replaces an older NAME/ only when all are written, and the
/// .vtm is committed last; on failure the older pair stays. `progress`: per block and array.
void write_vtm(const mesh::Mesh& mesh, const std::string& path, const ProgressCallback& progress = {});
/// The same with the equispaced node positions given.
void write_vtm(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
               const ProgressCallback& progress = {});

/// The folder of write_vtm's pieces: `path` without its extension.
std::string vtm_piece_folder(const std::string& path);

}  // namespace semimesh::io
