// 2D meshes of CAD surfaces, built in the surface's parameter space and measured in 3D.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/surface/curve_discretisation.hpp"
#include "semimesh/surface/size_field.hpp"

#include <array>
#include <vector>

namespace semimesh::surface {

using cad::Vec2;

/// Where a surface mesh node comes from. Interior nodes have curve == -1. A boundary node is node
/// `index` of the mesh of `curve` (parameter t); at a CAD vertex, `vertex` is its id as well.
struct NodeOrigin {
  int curve = -1;
  int index = -1;
  double t = 0.0;
  int vertex = -1;
  bool on_boundary() const { return curve >= 0; }
};

/// Triangles and quads of one surface. Elements are counter-clockwise seen from the fluid side:
/// (p1 - p0) x (p2 - p0) agrees with Surface::normal.
struct SurfaceMesh {
  int surface = -1;
  std::vector<Vec2> uv;                      ///< [nodes] parameters
  std::vector<Vec3> points;                  ///< [nodes] S(uv); boundary nodes: the curve mesh point
  std::vector<NodeOrigin> origin;            ///< [nodes]
  std::vector<std::array<int, 3>> triangles; ///< [triangles][3] node ids
  std::vector<std::array<int, 4>> quads;     ///< [quads][4] node ids
  int num_nodes() const { return static_cast<int>(points.size()); }
};

struct SurfaceMeshOptions {
  double split_factor = 1.3;  ///< refine while a triangle's longest 3D edge exceeds this times h
  int improvement_passes = 4; ///< rounds of (short-edge collapses, edge swaps, smoothing), measured in 3D
};

/// Unstructured triangles: constrained Delaunay triangulation of the boundary loops (outer and
/// holes) in parameter space, refined where 3D edges are longer than the size field asks (points
/// at the circumcentre in the local surface metric), then improved in 3D by collapsing too short
/// interior edges, edge swaps and smoothing. Boundary edges are exactly the curve mesh segments.
/// Periodic faces are cut open along their seams (a seam's nodes appear once per side, one period
/// apart in (u, v), same point and origin); a pole's side of the parameter box is one boundary
/// segment whose triangle is dropped, so the triangles around the pole form a fan in space.
/// Throws SurfaceMeshError when a curve node does not lie on the surface, the loops intersect in
/// parameter space, or the surface uses a curve twice in the same direction.
SurfaceMesh mesh_surface(const cad::Model& model, int surface, const CurveMeshes& curves, const SizeField& size,
                         const SurfaceMeshOptions& options = {});

/// Structured strip on a surface bounded by one loop of four curve uses: opposite curves must have
/// equal segment counts. Nodes by transfinite interpolation of the boundary parameters; quads, or
/// each quad split into two triangles along its diagonal with the larger minimum 3D angle.
/// Throws SurfaceMeshError naming the surface and the counts when it is not such a strip.
SurfaceMesh mesh_surface_structured(const cad::Model& model, int surface, const CurveMeshes& curves,
                                    bool split_into_triangles = false);

}  // namespace semimesh::surface
