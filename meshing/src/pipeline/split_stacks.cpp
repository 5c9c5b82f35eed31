#include "semimesh/pipeline/split_stacks.hpp"

#include <stdexcept>

namespace semimesh::pipeline {

StackSplit split_stacks(const mesh::Mesh& mesh, const std::vector<nearfield::LayerStack>& stacks,
                        const FamilySplit& wing, const FamilySplit& wall) {
  StackSplit result;
  result.mesh = mesh;
  // [stacks] the current pieces of each stack (indices into result.mesh), first layer first
  std::vector<std::vector<std::size_t>> pieces(stacks.size());
  for (std::size_t s = 0; s < stacks.size(); ++s) pieces[s] = {stacks[s].element};
  for (const nearfield::LayerFamily family : {nearfield::LayerFamily::Wing, nearfield::LayerFamily::Wall}) {
    const FamilySplit& how = family == nearfield::LayerFamily::Wing ? wing : wall;
    std::vector<ho::DirectedSplit> split;
    for (std::size_t s = 0; s < stacks.size(); ++s)
      for (const nearfield::LayerDirection& d : stacks[s].directions)
        if (d.family == family)
          for (std::size_t piece : pieces[s]) split.push_back({piece, d.axis});
    if (split.empty() || how.distribution.layers == 1) continue;
    std::vector<std::size_t> first;
    ho::SplitStats& stats = family == nearfield::LayerFamily::Wing ? result.wing : result.wall;
    result.mesh = ho::split_layers(result.mesh, split, how.distribution, how.ratio, &stats, &first);
    ++result.split_passes;
    // A split piece becomes `layers` consecutive pieces; the first layer of a stack in this family
    // is the first of them, so the pieces touching the body in both families come first.
    std::vector<char> was_split(first.size(), 0);
    for (const ho::DirectedSplit& d : split) was_split[d.element] = 1;
    for (auto& list : pieces) {
      std::vector<std::size_t> next;
      for (std::size_t piece : list) {
        const int count = was_split[piece] ? how.distribution.layers : 1;
        for (int k = 0; k < count; ++k) next.push_back(first[piece] + k);
      }
      list.swap(next);
    }
  }
  for (const auto& list : pieces) result.first_layer.push_back(list.front());
  return result;
}

}  // namespace semimesh::pipeline
