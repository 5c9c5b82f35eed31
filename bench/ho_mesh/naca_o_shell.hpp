// The benches' common input: the NACA 0012 O-shell (sharp TE, span 1.5) as a linear prism mesh.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <memory>

namespace semimesh::bench {

struct NacaOShell {
  std::unique_ptr<cad::Model> model;
  mesh::Mesh linear;  ///< order 1, one prism per wing surface triangle
};

NacaOShell naca_o_shell();

}  // namespace semimesh::bench
