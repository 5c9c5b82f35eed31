// The volume regions writers emit (one physical volume / Nektar++ composite each).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace semimesh::io {

/// Region names, index = region id.
std::vector<std::string> region_names(const mesh::Mesh& mesh);
/// Region id of element e.
int element_region(const mesh::Mesh& mesh, std::size_t e);

}  // namespace semimesh::io
