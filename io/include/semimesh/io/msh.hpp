// Gmsh MSH files, versions 4.1 (binary or ASCII) and 2.2 (ASCII) (gmsh.info/doc/texinfo, "MSH file format").
//
// Written: $MeshFormat, $PhysicalNames (one dim-2 group per boundary group, tags 1..G in the
// mesh's group order, then one dim-3 group per volume region that has elements, tags G+1.. in
// region order: physical tags are unique across dimensions, as PyFR requires, and so are names
// ignoring case: a region named like a boundary group is written NAME_volume), $Entities (4.1:
// one surface per boundary group, one volume per region), $Nodes (every mesh node, tag = NodeId + 1,
// equispaced positions), $Elements (volume elements by region and shape, then boundary faces by
// group and shape, in mesh order inside each block; element tags from 1).
// MSH 4.1 can be written binary (file-type 1, little endian, data-size 8: ints for entity tags and
// types, size_t for counts and node/element tags): about half the bytes, several times faster;
// Gmsh reads it, PyFR does not (ASCII only).
// Node order inside an element is the canonical Gmsh order, so it is written as stored.
// Orders 1..9 (kMaxMshOrder). A GLL mesh is written at its equispaced nodes (io::EquispacedNodes).
#pragma once

#include "semimesh/io/equispaced.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <string>

namespace semimesh::io {

enum class MshVersion { V41, V22 };
enum class MshEncoding { Ascii, Binary };

/// Writes atomically (see atomic_file.hpp). Throws std::invalid_argument for an unsupported order
/// or for binary MSH 2.2, std::runtime_error for I/O failures (message names the file). `progress`:
/// the fraction of nodes and elements written, throttled.
void write_msh(const mesh::Mesh& mesh, const std::string& path, MshVersion version = MshVersion::V41,
               MshEncoding encoding = MshEncoding::Ascii, const ProgressCallback& progress = {});
/// The same with the equispaced node positions given (computed once for several formats).
void write_msh(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
               MshVersion version = MshVersion::V41, MshEncoding encoding = MshEncoding::Ascii,
               const ProgressCallback& progress = {});

/// Reads an MSH 4.1 (ASCII or binary: little endian, data-size 8) or ASCII 2.2 file: 3D elements become mesh elements, triangles and quads
/// become boundary faces in the group named by their physical group ("surface_<tag>" when the
/// group has no name, "unassigned" without a physical group); points and lines are skipped.
/// All elements must have one order (1..9). The node set is Equispaced. Throws std::runtime_error
/// "FILE:LINE: what was expected" on malformed input (binary data: LINE is its section's first).
/// A binary file may hold no point or line elements (their records cannot be sized).
mesh::Mesh read_msh(const std::string& path);

}  // namespace semimesh::io
