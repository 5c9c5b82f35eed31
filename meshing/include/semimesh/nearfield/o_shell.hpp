// The O-type near field: one layer of prisms of thickness delta around the whole body (paper,
// section "Partitioning"; docs/architecture.md).
//
// Every body triangle (a, b, c) becomes the prism (a, b, c, a', b', c') with x' = x + delta_x n_x
// along the node normal (node_normals.hpp). Where the body meets the wall, the normals lie in the
// wall and the offsets are projected onto it, so the layer's root quads lie on the wall.
// The thickness delta_x starts at `thickness` everywhere and is reduced locally where
//  - a prism would not be valid (certified Jacobian, ho::certify_jacobian) or would be nearly flat
//    at one of its vertices (concave curvature: neighbouring offsets cross), or
//  - an offset point comes closer than half its thickness to a part of the body that is not its own
//    neighbourhood (proximity: two layers would overlap),
// by a factor per round, then limited by a gradation (|delta_x - delta_y| <= g |x - y|) so the
// layer stays smooth. Each reduced region gives a Warning with its place; a node that would need
// less than min_thickness_fraction * thickness is an error naming the place.
//
// Boundary orientation (all out of the near-field domain): group "wing" holds the body triangles
// reversed, (a, c, b), whose normal points INTO the body; group "wall" holds the root quads
// (a, b, b', a') over each body edge on the wall, normal -z (into the wall). The skin faces
// (a', b', c') point out of the near field, and the footprint runs counter-clockwise seen from the
// fluid side of the wall.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/near_field.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <vector>

namespace semimesh::nearfield {

/// Keys, ranges and meanings: shell_keys() (the config's [nearfield] section).
struct ShellParams {
  double thickness = 0.1;
  int normal_smoothing_passes = 10;
  double min_thickness_fraction = 0.1;
  double reduction_factor = 0.7;
  double gradation = 0.5;
};

/// One row per key of ShellParams (semimesh/params/table.hpp).
const params::Table<ShellParams>& shell_keys();

/// CAD surface ids of the body (meshed, extruded) and of the wall it stands on (-1: no wall, the
/// body must then be closed).
struct BodyRoles {
  std::vector<int> body_surfaces;
  int wall_surface = -1;
};

/// Body surface meshes -> one prism layer (order 1). Throws NearFieldError naming the parameter,
/// or the surface and the place, when the layer cannot be built.
NearField build_o_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params);

}  // namespace semimesh::nearfield
