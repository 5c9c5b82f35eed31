#include "semimesh/surface/model_surfaces.hpp"

#include "semimesh/cad/labels.hpp"

#include "semimesh/surface/error.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <mutex>
#include <vector>

namespace semimesh::surface {
namespace {

using EdgeKey = std::array<double, 6>;  // the two end points, lexicographically ordered

EdgeKey edge_key(const Vec3& a, const Vec3& b) {
  const std::array<double, 3> pa{a.x(), a.y(), a.z()}, pb{b.x(), b.y(), b.z()};
  const auto& lo = std::min(pa, pb);
  const auto& hi = std::max(pa, pb);
  return {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
}

// Edges used by exactly one element of the mesh, by their 3D points.
std::map<EdgeKey, int> boundary_edges(const SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  auto add_ring = [&](const int* nodes, int count) {
    for (int i = 0; i < count; ++i) ++uses[std::minmax(nodes[i], nodes[(i + 1) % count])];
  };
  for (const auto& t : mesh.triangles) add_ring(t.data(), 3);
  for (const auto& q : mesh.quads) add_ring(q.data(), 4);
  std::map<EdgeKey, int> edges;
  for (const auto& [e, count] : uses)
    if (count == 1) ++edges[edge_key(mesh.points[e.first], mesh.points[e.second])];
  return edges;
}

}  // namespace

int SurfaceMeshes::num_triangles() const {
  int n = 0;
  for (const auto& s : surfaces) n += static_cast<int>(s.triangles.size());
  return n;
}

int SurfaceMeshes::num_quads() const {
  int n = 0;
  for (const auto& s : surfaces) n += static_cast<int>(s.quads.size());
  return n;
}

SurfaceMeshes mesh_model_surfaces(const cad::Model& model, const SizeField& size, const ModelMeshOptions& options,
                                  const ProgressCallback& progress) {
  for (int s : options.structured_surfaces)
    if (s < 0 || s >= model.num_surfaces())
      throw SurfaceMeshError("structured surface id " + std::to_string(s) + " is out of range: the model has " +
                             std::to_string(model.num_surfaces()) + " surfaces");
  SurfaceMeshes out;
  // Progress: the curves count as one item, each surface as one.
  const double items = 1.0 + model.num_surfaces();
  if (progress) progress(0.0, "curves");
  std::vector<CurveMesh> curves = discretise_all_curves(model, size, options.curve_counts, options.min_segments).all();
  equalise_strip_counts(model, size, options.structured_surfaces, options.curve_counts, curves);
  out.curves = CurveMeshes(std::move(curves));
  // Each surface is meshed on its own from the shared curves' nodes, so the surfaces go to every
  // thread when the model allows it, each writing its own slot (each mesh is the same whatever the
  // threads); the lowest failing surface's error is rethrown, as one after another.
  const int num_surfaces = model.num_surfaces();
  out.surfaces.resize(static_cast<std::size_t>(num_surfaces));
  std::mutex mutex;
  int done = 0, failed_at = num_surfaces;
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) if (model.thread_safe())
  for (int s = 0; s < num_surfaces; ++s) {
    try {
      out.surfaces[static_cast<std::size_t>(s)] =
          options.structured_surfaces.count(s) ? mesh_surface_structured(model, s, out.curves, options.split_structured)
                                               : mesh_surface(model, s, out.curves, size, options.surface);
      const std::lock_guard<std::mutex> lock(mutex);  // whichever thread ends a surface reports it
      if (progress) progress((1.0 + ++done) / items, model.surface(s).name());
    } catch (...) {  // may not leave the parallel region
      const std::lock_guard<std::mutex> lock(mutex);
      if (s < failed_at) failed_at = s, error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  if (progress) progress(1.0, "");
  return out;
}

std::vector<std::string> check_conformity(const cad::Model& model, const SurfaceMeshes& meshes) {
  std::vector<std::string> problems;
  if (static_cast<int>(meshes.surfaces.size()) != model.num_surfaces())
    return {"expected " + std::to_string(model.num_surfaces()) + " surface meshes, got " +
            std::to_string(meshes.surfaces.size())};
  std::vector<std::map<EdgeKey, int>> open(meshes.surfaces.size());  // [surfaces] unmatched boundary edges
  for (std::size_t s = 0; s < meshes.surfaces.size(); ++s) open[s] = boundary_edges(meshes.surfaces[s]);

  for (int c = 0; c < model.num_curves(); ++c) {
    if (model.curve(c).is_degenerate()) continue;  // a point: its segment is no edge of any mesh
    const CurveMesh& cm = meshes.curves.at(c);
    for (const cad::SurfaceUse& use : model.surfaces_of_curve(c))
      for (int k = 0; k < cm.segments(); ++k) {
        auto& edges = open[use.surface];
        auto found = edges.find(edge_key(cm.points[k], cm.points[k + 1]));
        if (found == edges.end()) {
          problems.push_back("segment " + std::to_string(k) + " of " + cad::curve_label(model, c) +
                             " is not a boundary edge of " + cad::surface_label(model, use.surface));
        } else if (--found->second == 0) {
          edges.erase(found);
        }
      }
  }
  // Around a pole the triangles meet in space along edges that are two boundary edges in (u, v)
  // (the two sides of the dropped pole triangle): a pair of them at a pole vertex is closed.
  std::vector<Vec3> poles;
  for (int c = 0; c < model.num_curves(); ++c)
    if (model.curve(c).is_degenerate()) poles.push_back(model.vertex(model.curve_vertices(c)[0]).point);
  for (auto& edges : open)
    for (auto it = edges.begin(); it != edges.end();) {
      const Vec3 a((*it).first[0], (*it).first[1], (*it).first[2]), b((*it).first[3], (*it).first[4], (*it).first[5]);
      const bool at_pole = std::any_of(poles.begin(), poles.end(), [&](const Vec3& p) { return p == a || p == b; });
      it = at_pole && it->second == 2 ? edges.erase(it) : std::next(it);
    }
  for (std::size_t s = 0; s < open.size(); ++s)
    if (!open[s].empty())
      problems.push_back(cad::surface_label(model, static_cast<int>(s)) + " has " + std::to_string(open[s].size()) +
                         " boundary edges that are not curve segments");
  return problems;
}

}  // namespace semimesh::surface
