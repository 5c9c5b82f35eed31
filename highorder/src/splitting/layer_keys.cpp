#include "semimesh/ho/splitting/split_layers.hpp"

namespace semimesh::ho {

const params::Table<LayerDistribution>& layer_keys() {
  static const params::Table<LayerDistribution> table = {
      params::integer("layers", &LayerDistribution::layers, "[1, 100]", "N, the layers each near-field element is split into"),
      params::real("ratio", &LayerDistribution::ratio, ">= 1", "r, height ratio of consecutive layers"),
  };
  return table;
}

}  // namespace semimesh::ho
