#include "semimesh/pipeline/split_stacks.hpp"

#include <utility>

namespace semimesh::pipeline {

namespace {

// Family 0 the wing's layers, 1 the wall's.
std::vector<ho::SplitFamily> families_of(const FamilySplit& wing, const FamilySplit& wall) {
  return {{wing.distribution, wing.ratio}, {wall.distribution, wall.ratio}};
}

// The split of each stack; a family of one layer leaves its directions unsplit.
std::vector<ho::LayerSplit> layer_splits(const std::vector<nearfield::LayerStack>& stacks,
                                         const std::vector<ho::SplitFamily>& families) {
  std::vector<ho::LayerSplit> split;
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
  return split;
}

}  // namespace

StackSplit split_stacks(mesh::Mesh mesh, const std::vector<nearfield::LayerStack>& stacks,
                        const FamilySplit& wing, const FamilySplit& wall, const ProgressCallback& progress,
                        bool inherit_bounds, ho::SplitEntities entities, const ho::PieceBoundsAhead* ahead) {
  const std::vector<ho::SplitFamily> families = families_of(wing, wall);
  const std::vector<ho::LayerSplit> split = layer_splits(stacks, families);
  StackSplit result;
  std::vector<ho::SplitStats> stats;
  std::vector<std::size_t> first;
  result.mesh = ho::split_layers(std::move(mesh), split, families, &stats, &first, progress,
                                 inherit_bounds ? &result.inherited : nullptr, entities, ahead);
  result.wing = stats[0];
  result.wall = stats[1];
  for (const nearfield::LayerStack& s : stacks) result.first_layer.push_back(first[s.element]);
  return result;
}

ho::PieceBoundsAhead piece_bounds_ahead(const mesh::Mesh& curved, const std::vector<nearfield::LayerStack>& stacks,
                                        const FamilySplit& wing, const FamilySplit& wall,
                                        const std::atomic<bool>& stop) {
  const std::vector<ho::SplitFamily> families = families_of(wing, wall);
  return ho::piece_bounds_ahead(curved, layer_splits(stacks, families), families, stop);
}

}  // namespace semimesh::pipeline
