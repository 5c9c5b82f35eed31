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

/// Opposite curves of each structured strip in `strips` (a loop of four curve uses) get equal segment
/// counts: a curve prescribed in `prescribed` imposes its count on the opposite one; otherwise the
/// smaller count is raised to the larger one, size-graded (discretise_curve_to_count). Repeated
/// until every strip agrees, so strips sharing curves agree too. Throws SurfaceMeshError naming
/// the surface and both curves when two prescribed opposite curves differ. Surfaces that are no
/// such strip, or whose side is a pole, are left to mesh_surface_structured's error.
void equalise_strip_counts(const cad::Model& model, const SizeField& size, const std::set<int>& strips,
                           const std::map<int, CurveCount>& prescribed, std::vector<CurveMesh>& curves);

/// Boundary edges (used by one element of their surface mesh) must each be a segment of a curve
/// mesh, and every curve segment must be a boundary edge of exactly as many surface meshes as the
/// model says the curve bounds (two on a closed model), with the very same two 3D points.
/// Returns one line per problem; empty when conforming.
std::vector<std::string> check_conformity(const cad::Model& model, const SurfaceMeshes& meshes);

}  // namespace semimesh::surface
