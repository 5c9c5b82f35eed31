// The far field: the unstructured region between the near field's outer skin, the wall and the
// far-field box (docs/architecture.md, section 1). Pyramids sit on the quads of the skin so that the rest of
// the region can be filled with tetrahedra; the tetrahedra come from TetGen.
//
// Licence: this stage links TetGen 1.5 (AGPL-3.0-or-later) and lives in its own target,
// semimesh_farfield, so that the rest of semimesh does not.
#pragma once

#include "semimesh/error.hpp"

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/near_field.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/progress.hpp"

#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::farfield {

class FarFieldError : public InputError {
 public:
  using InputError::InputError;
};

/// Keys, ranges and meanings: far_field_keys() (the config's [farfield] section).
struct FarFieldParams {
  double box_size = 2.0;
  double wall_size = 1.0;
  double growth = 1.2;
  double radius_edge_ratio = 1.5;
  double max_volume = 0.0;
  std::string symmetry = "none";
};

/// One row per key of FarFieldParams (semimesh/params/table.hpp).
const params::Table<FarFieldParams>& far_field_keys();

struct FarFieldStats {
  int tets = 0;
  int pyramids = 0;
  int wall_triangles = 0;
  int box_triangles = 0;
  int wall_layer_prisms = 0;
  int symmetry_faces = 0;  ///< far-field faces moved to group "symmetry" (farfield.symmetry)
  int interior_points = 0;  ///< points given to TetGen inside the region (interior_points.hpp)
  int added_points = 0;     ///< points TetGen's refinement added
  double seconds_tetgen = 0;
  bool tetgen_untied = false;  ///< TetGen's mesh of the untied boundary was taken (tetgen_volume.hpp)
};

struct FarField {
  mesh::Mesh mesh;  ///< the near field's mesh with the far field added
  FarFieldStats stats;
  std::vector<nearfield::LayerStack> stacks;  ///< every layer element of the mesh: the near field's, then the wall layer's
};

/// The whole mesh: the near field's mesh with far-field nodes, pyramids (one on each quad of
/// near.skin, vertices 0..3 the quad, 4 the apex) and TetGen tetrahedra (region "farfield"), and
/// the boundary faces "wall" (the far-field part of the wall, normal out of the domain) and
/// "farfield" (the box faces, normal out of the domain).
/// The skin faces and the footprint are kept exactly: the far field conforms with the near field.
/// The near field is taken by value: pass it with std::move when it is not needed afterwards.
///  box_surfaces  CAD surface ids of the box faces; their curve meshes are shared with the wall's
///                outer loop.
///  wall_surface  the wall; its outer loop bounds the wall region, nf.footprint the hole. A planar
///                wall is triangulated in its plane, a curved one (a fuselage) in its parameters
///                scaled to lengths at the root, edges turning at most 1/4 radian on it.
/// Tetrahedron sizes grow from the local skin edge length towards the box size by TetGen's quality
/// bound alone (-q radius_edge_ratio; no background size, which over-refined about 8 times on the
/// NACA0012 case); `growth` grades the wall region and the box curves.
/// With a wall layer (wall_layer_thickness > 0: a C-type near field, whose footprint_top gives the
/// layer's tops over its footprint) the wall triangles carry prisms of that thickness (region
/// "wall_layer", wall_layer.hpp): their tops bound the tetrahedra, the box faces start on the
/// layer's top.
/// Throws FarFieldError naming the parameter, surface or region at fault (e.g. TetGen's failure
/// translated: self-intersecting boundary, too close facets). `progress` is told the start of each
/// sub-step (steps "box and wall", "wall layer", "TetGen", "elements") and the end.
/// `beside` (optional): work that only speeds up later stages, run on another thread while TetGen's
/// process works (its first try), given the mesh so far (every element but the tetrahedra, which
/// come after them; the mesh is not changed meanwhile), the layer stacks so far (the near field's
/// and the wall layer's: FarField::stacks) and a flag set when TetGen has answered,
/// after which it is waited for (it should then return soon). Its exceptions are dropped: the
/// stages after must not need what it computes. The mesh built is the same with or without it.
using BesideTetgen = std::function<void(const mesh::Mesh& so_far, const std::vector<nearfield::LayerStack>& stacks,
                                        const std::atomic<bool>& stop)>;
FarField build_far_field(const cad::Model& model, nearfield::NearField near, const FarFieldParams& params,
                         const std::vector<int>& box_surfaces, int wall_surface, double wall_layer_thickness = 0.0,
                         const ProgressCallback& progress = {}, const BesideTetgen& beside = {});

}  // namespace semimesh::farfield
