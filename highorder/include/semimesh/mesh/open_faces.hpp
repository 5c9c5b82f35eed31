// A mesh's open faces: those one element uses and no boundary face covers (where two parts of a
// mesh meet before they are joined, each side's copy of a face; the outside of a mesh without
// boundary faces).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <algorithm>
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
  for (const Element& el : m.elements())
    for (std::uint32_t f = 0; f < ho::faces(el.shape).size(); ++f) uses[el.faces[f]] += uses[el.faces[f]] < 2;
  for (const BoundaryFace& b : m.boundary_faces()) uses[b.face] = 2;
  // The users of the few faces used once, found again (no user kept for every face).
  std::vector<OpenFace> open;
  for (std::uint32_t e = 0; e < m.elements().size(); ++e) {
    const Element& el = m.elements()[e];
    for (std::uint32_t f = 0; f < ho::faces(el.shape).size(); ++f)
      if (uses[el.faces[f]] == 1) open.push_back({el.faces[f], e, static_cast<std::uint8_t>(f)});
  }
  std::sort(open.begin(), open.end(), [](const OpenFace& a, const OpenFace& b) { return a.face < b.face; });
  return open;
}

}  // namespace semimesh::mesh
