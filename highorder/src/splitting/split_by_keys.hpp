// The reference of split_layers' node naming, for tests: every node of every piece named by its
// key (Splitter::key_of) and looked up, as split_layers named them before it named each element's
// distinct nodes once from a recipe per shape, plan and layer counts. The same mesh, node for node.
#pragma once

#include "semimesh/ho/splitting/split_layers.hpp"

#include <vector>

namespace semimesh::ho::detail {

mesh::Mesh split_layers_by_keys(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                                const std::vector<SplitFamily>& families,
                                std::vector<InheritedBounds>* inherited = nullptr);

}  // namespace semimesh::ho::detail
