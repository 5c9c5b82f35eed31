// A mesh's open faces: those one element uses and no boundary face covers (where two parts of a
// mesh meet before they are joined, each side's copy of a face; the outside of a mesh without
// boundary faces).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <cstdint>
#include <vector>

namespace semimesh::mesh {

struct OpenFace {
  std::uint32_t face = 0;     ///< the face entity
  std::uint32_t element = 0;  ///< the one element using it
  std::uint8_t local = 0;     ///< its local face there (ho::faces order)
};

/// The open faces of `m`, by face id.
inline std::vector<OpenFace> open_faces(const Mesh& m) {
  std::vector<std::uint8_t> uses(m.faces().size(), 0);  // 0, 1, 2: two or more (or a boundary face)
  std::vector<OpenFace> user(m.faces().size());
  for (std::uint32_t e = 0; e < m.elements().size(); ++e) {
    const Element& el = m.elements()[e];
    for (std::uint32_t f = 0; f < ho::faces(el.shape).size(); ++f) {
      const std::uint32_t face = el.faces[f];
      if (uses[face] == 0) user[face] = {face, e, static_cast<std::uint8_t>(f)};
      if (uses[face] < 2) ++uses[face];
    }
  }
  for (const BoundaryFace& b : m.boundary_faces()) uses[b.face] = 2;
  std::vector<OpenFace> open;
  for (std::size_t face = 0; face < uses.size(); ++face)
    if (uses[face] == 1) open.push_back(user[face]);
  return open;
}

}  // namespace semimesh::mesh
