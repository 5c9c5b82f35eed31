#include "regions.hpp"

namespace semimesh::io {

// Until elements carry a region, every element is in the one region "fluid".
std::vector<std::string> region_names(const mesh::Mesh&) { return {"fluid"}; }

int element_region(const mesh::Mesh&, std::size_t) { return 0; }

}  // namespace semimesh::io
