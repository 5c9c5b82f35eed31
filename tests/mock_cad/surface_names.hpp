// The names of a model's surfaces in id order (tests of the documented face order).
#pragma once

#include "semimesh/cad/model.hpp"

#include <string>
#include <vector>

namespace naca_test {

inline std::vector<std::string> surface_names(const semimesh::cad::Model& m) {
  std::vector<std::string> out;
  for (int s = 0; s < m.num_surfaces(); ++s) out.push_back(m.surface(s).name());
  return out;
}

}  // namespace naca_test
