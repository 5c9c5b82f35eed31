// All curves and surfaces of a model meshed together, and the conformity check between them.
#pragma once

#include "semimesh/progress.hpp"
#include "semimesh/surface/surface_mesh.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace semimesh::surface {

struct ModelMeshOptions {
  std::map<int, CurveCount> curve_counts;  ///< prescribed curve discretisations, by curve id
  int min_segments = 1;                     ///< per size-driven curve
  std::set<int> structured_surfaces;       ///< surface ids meshed as structured strips
  bool split_structured = false;           ///< triangles instead of quads on those strips
  SurfaceMeshOptions surface;
};

struct SurfaceMeshes {
  CurveMeshes curves;
  std::vector<SurfaceMesh> surfaces;  ///< [num_surfaces], indexed by surface id
  int num_triangles() const;
  int num_quads() const;
};

/// Meshes every curve, then every surface. Errors name the surface that failed. `progress` is told
/// before the curves (step "curves") and before each surface (step: its name), and at the end.
SurfaceMeshes mesh_model_surfaces(const cad::Model& model, const SizeField& size, const ModelMeshOptions& options = {},
                                  const ProgressCallback& progress = {});

/// Boundary edges (used by one element of their surface mesh) must each be a segment of a curve
/// mesh, and every curve segment must be a boundary edge of exactly as many surface meshes as the
/// model says the curve bounds (two on a closed model), with the very same two 3D points.
/// Returns one line per problem; empty when conforming.
std::vector<std::string> check_conformity(const cad::Model& model, const SurfaceMeshes& meshes);

}  // namespace semimesh::surface
