// A half model (a wing-body cut at its plane of symmetry): the far field's side on that plane is a
// symmetry plane, whose faces a solver must tell from the far field's. They leave boundary group
// "farfield" for "symmetry", found by position: every vertex on the plane. The box faces, the wall
// layer's sides and the wake's outflow faces are all "farfield" faces until then, so one pass over
// the finished far field names them all.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>

namespace semimesh::farfield {

/// The far field's sides a symmetry plane can be on, as farfield.symmetry names them.
inline constexpr const char* kSymmetrySides[] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

/// Moves every "farfield" boundary face of `mesh` whose vertices all lie within `tolerance` of the
/// far field's extreme coordinate on `side` (the least or greatest over the "farfield" faces'
/// vertices; side one of kSymmetrySides) to group "symmetry". Returns how many moved. Throws
/// FarFieldError naming farfield.symmetry when no face lies there (a sphere, a side the far field
/// does not have flat).
int move_symmetry_faces(mesh::Mesh& mesh, const std::string& side, double tolerance);

}  // namespace semimesh::farfield
