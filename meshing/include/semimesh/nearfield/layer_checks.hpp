// The two tests that decide where the prism layer must be thinner.
#pragma once

#include "semimesh/nearfield/body_mesh.hpp"

#include <array>
#include <vector>

namespace semimesh::nearfield {

/// A prism (vertices 0,1,2 on the body, 3,4,5 their offsets) is sound when its Jacobian is
/// certified positive over the whole element (ho::certify_jacobian) and, at every vertex pair i,
/// i+3, the Jacobian at the offset vertex is at least `min_outer_ratio` of the one at the body
/// vertex, which must be at least 1e-9 of the product of its edges there (a flat body triangle is
/// no prism, whatever the sign of its round-off): a concave fan whose offsets converge (about to cross) fails the second test before the
/// first. Both tests pass for any thin enough layer when the node normals see their triangles.
bool prism_is_sound(const std::array<Vec3, 6>& vertices, double min_outer_ratio = 0.1);

/// [nodes] true where the offset point outer[i] lies closer than half of thickness[i] to a body
/// triangle that is not in the node's own neighbourhood (no vertex within a mesh path length of
/// 1.5 thickness[i]): there the layers of two parts of the body would overlap.
/// The triangles near each offset point come from a bounding-box tree of the triangles, pruned at
/// half the thickness: O(nodes log nodes). (The plain scan over all triangles made the near field
/// grow quadratically: 52 s at 174k prisms; a uniform grid of cells as wide as that reach, the
/// layer's thickness, still did, its cells holding ever more triangles as the mesh is refined:
/// 13 s of the near field's 24 at 16.5 M elements.)
std::vector<char> crowded_nodes(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours,
                                const std::vector<Vec3>& outer, const std::vector<double>& thickness);

/// The same by testing every triangle for every node: the slow, obviously right reference.
std::vector<char> crowded_nodes_by_scan(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours,
                                        const std::vector<Vec3>& outer, const std::vector<double>& thickness);

/// Distance from p to the triangle (a, b, c) (ho::closest_point_on_triangle).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace semimesh::nearfield
