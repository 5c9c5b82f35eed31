// Tests that fold a mesh and repair it keep working on one mesh variable.
#pragma once

#include "semimesh/ho/repair.hpp"

#include <utility>

namespace semimesh::ho {

/// repair_invalid, with the repaired mesh put back into `mesh`.
inline RepairStats repair_in_place(mesh::Mesh& mesh, const cad::Model& model, const std::vector<std::size_t>& elements) {
  Repaired repaired = repair_invalid(mesh, model, elements);
  mesh = std::move(repaired.mesh);
  return repaired.stats;
}

}  // namespace semimesh::ho
