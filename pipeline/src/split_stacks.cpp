#include "semimesh/pipeline/split_stacks.hpp"

#include <algorithm>
#include <utility>

namespace semimesh::pipeline {

StackSplit split_stacks(mesh::Mesh mesh, const std::vector<nearfield::LayerStack>& stacks,
                        const FamilySplit& wing, const FamilySplit& wall, const ProgressCallback& progress,
                        bool inherit_bounds, const std::vector<ho::InheritedBounds>* unsplit) {
  const std::size_t input_elements = mesh.elements().size();
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
                                 inherit_bounds ? &result.inherited : nullptr);
  result.wing = stats[0];
  result.wall = stats[1];
  for (const nearfield::LayerStack& s : stacks) result.first_layer.push_back(first[s.element]);
  if (inherit_bounds && unsplit && !unsplit->empty()) {
    std::vector<char> is_split(input_elements, 0);
    for (const ho::LayerSplit& one : split) is_split[one.element] = 1;
    for (const ho::InheritedBounds& b : *unsplit)
      if (b.element < input_elements && !is_split[b.element])
        result.inherited.push_back({first[b.element], b.fingerprint, b.bounds});
    std::sort(result.inherited.begin(), result.inherited.end(),
              [](const ho::InheritedBounds& a, const ho::InheritedBounds& b) { return a.element < b.element; });
  }
  return result;
}

}  // namespace semimesh::pipeline
