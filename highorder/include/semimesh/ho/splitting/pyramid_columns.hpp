// Pyramids only on parallelogram bases, for PyFR (its importer, pyfr/readers/base.py
// `_check_pyr_parallelogram`, refuses a pyramid whose first-order base corners miss
// x0 - x1 - x2 + x3 = 0 by more than 1e-10 in a coordinate; docs/solvers.md).
//
// A quad that is not a parallelogram can only be closed off by elements with quad faces of their own
// (hex, prism), so the fix cannot stay local to the pyramid: the quad's hex is split into two prisms
// whose triangles lie on the quad and on the opposite face, which makes the next hex across that
// face split the same way, and so on through the whole column of hexes to its other end: a pyramid
// (split into two tetrahedra on the same diagonal) or a boundary quad (split into two triangles).
// Every new node sits where the original element's own map puts it (the prism is the hex's map
// restricted to half the hex, the tetrahedron the pyramid's), so the geometry is the original one up
// to the interpolation of that map at order P.
//
// What cannot be done this way is refused once every column has been walked (std::invalid_argument
// naming the first element of each kind, its region and a point, and how many there are): a column
// that runs into a prism or tetrahedron, or a hex that two columns would split along two different
// axes (e.g. a block's edge where two of its faces carry such pyramids).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <cstddef>

namespace semimesh::ho {

struct PyramidColumnStats {
  std::size_t pyramids_refused = 0;  ///< pyramids whose base failed the parallelogram test
  std::size_t columns = 0;           ///< hex columns split (each under one or two such pyramids)
  std::size_t hexes_split = 0;       ///< each into two prisms
  std::size_t pyramids_split = 0;    ///< each into two tetrahedra (the refused ones and the columns' other ends)
  std::size_t boundary_quads_split = 0;  ///< each into two boundary triangles
};

struct PyramidColumns {
  mesh::Mesh mesh;
  PyramidColumnStats stats;
};

/// True if the pyramid's first-order base corners (vertices 0..3, Gmsh order) form a parallelogram:
/// |x0 - x1 + x2 - x3| <= tolerance in each coordinate (PyFR's test, written with its face order).
bool has_parallelogram_base(const mesh::Mesh& mesh, std::size_t pyramid, double tolerance);

/// A new mesh of the same order and node set in which every pyramid failing has_parallelogram_base
/// is gone: its base's hex column split into prisms and the pyramids at the column's ends into
/// tetrahedra, all on one diagonal per column (the shorter one of the first such base met). Other
/// elements and boundary faces are copied; a split element's pieces take its place and region.
/// Nodes: the input's (with their CAD attachments) that remain in use, then the new ones.
/// Taken by value: a mesh moved in comes back as it is, not copied, when no pyramid is refused.
PyramidColumns split_pyramid_columns(mesh::Mesh mesh, double tolerance);

}  // namespace semimesh::ho
