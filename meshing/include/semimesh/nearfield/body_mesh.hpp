// The body (wing) as one triangle mesh: the surface meshes of the body surfaces glued through their
// shared curve-mesh nodes.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <array>
#include <utility>
#include <vector>

namespace semimesh::nearfield {

using cad::Vec3;

struct BodyMesh {
  std::vector<Vec3> points;                    ///< [nodes]
  std::vector<mesh::CadAttachment> cad;        ///< [nodes] vertex, curve (t) or surface (u, v)
  std::vector<int> node_surface;               ///< [nodes] one body surface the node lies on (for messages)
  std::vector<std::array<int, 3>> triangles;   ///< [triangles] counter-clockwise seen from the fluid
  std::vector<int> triangle_surface;           ///< [triangles] CAD surface id
  int num_nodes() const { return static_cast<int>(points.size()); }
};

/// Glues the surface meshes of `body_surfaces`. A boundary node is identified by its CAD vertex if
/// it has one, else by (curve, index in the curve mesh), so neighbouring surfaces share it exactly;
/// interior nodes are attached to their surface with their (u, v).
/// Throws NearFieldError naming the surface when an id is not a surface of the model, a body
/// surface has no mesh or holds quads (the O-type shell extrudes triangles into prisms).
BodyMesh merge_body_meshes(const cad::Model& model, const surface::SurfaceMeshes& meshes,
                           const std::vector<int>& body_surfaces);

/// Edges used by exactly one triangle, as directed in that triangle: [edges] (a, b).
/// Throws NearFieldError at an edge used by more than two triangles or twice in one direction
/// (inconsistent orientation), naming the place.
std::vector<std::pair<int, int>> open_edges(const BodyMesh& body);

/// Neighbouring nodes of each node through triangle edges: [nodes][neighbours].
std::vector<std::vector<int>> node_neighbours(const BodyMesh& body);

}  // namespace semimesh::nearfield
