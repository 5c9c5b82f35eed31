#include "semimesh/pipeline/split_stacks.hpp"

#include <utility>

namespace semimesh::pipeline {

StackSplit split_stacks(mesh::Mesh mesh, const std::vector<nearfield::LayerStack>& stacks,
                        const FamilySplit& wing, const FamilySplit& wall, const ProgressCallback& progress,
                        bool inherit_bounds, ho::SplitEntities entities) {
  // Family 0 the wing's layers, 1 the wall's; a family of one layer leaves its directions unsplit.
  const std::vector<ho::SplitFamily> families = {{wing.distribution, wing.ratio}, {wall.distribution, wall.ratio}};
  std::vector<ho::LayerSplit> split;
  std::vector<std::size_t> stack_of_split;
  for (std::size_t s = 0; s < stacks.size(); ++s) {
    ho::LayerSplit one{stacks[s].element, {-1, -1}, {0, 0}};
    int slot = 0;
    for (const nearfield::LayerDirection& d : stacks[s].directions) {
      const int family = d.family == nearfield::LayerFamily::Wing ? 0 : 1;
      if (families[family].distribution.layers == 1) continue;
      one.direction[slot] = d.axis, one.family[slot] = family;
      ++slot;
    }
    if (slot > 0) split.push_back(one);
  }
  StackSplit result;
  std::vector<ho::SplitStats> stats;
  std::vector<std::size_t> first;
  result.mesh = ho::split_layers(std::move(mesh), split, families, &stats, &first, progress,
                                 inherit_bounds ? &result.inherited : nullptr, entities);
  result.wing = stats[0];
  result.wall = stats[1];
  for (const nearfield::LayerStack& s : stacks) result.first_layer.push_back(first[s.element]);
  return result;
}

}  // namespace semimesh::pipeline
