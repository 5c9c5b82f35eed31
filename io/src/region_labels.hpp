// The names the writers give the mesh's regions: its own, but that a region named like a boundary
// group (the "farfield" region beside the "farfield" surface), ignoring case, is "<name>_volume".
// Gmsh physical names must be unique (PyFR refuses "Duplicate physical name"), and a Nektar++ file
// reading three composites "farfield" (tets, pyramids, the outer faces) misleads its user.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace semimesh::io::detail {

/// One label per region of `m`, in region order.
std::vector<std::string> region_labels(const mesh::Mesh& m);

}  // namespace semimesh::io::detail
