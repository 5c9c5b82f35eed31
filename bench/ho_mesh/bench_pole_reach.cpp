// The pole chart's reach (CurvingParams::pole_reach, highorder/src/curving/pole_chart.hpp) measured
// on the NekMesh STEP wing's revolved tip: its pole's neighbourhood meshed as the example does
// (examples/nekmesh_wing.toml: 4 segments a radian of curvature, gradation 1.2, a 20 mm shell split
// into 6 layers of ratio 1.5), curved at order 4 with each reach. For the prisms in each band of
// distance to the pole, counted in their own longest sides (band k: a vertex within k sides, none
// within k - 1; band 0: touching the pole), it prints the max geometric error and the min scaled
// Jacobian of the shell and of its split layers. A second table halves the sizes near the pole.
// Prints tables; not a test.
// Usage: bench_pole_reach [STEP file]   (default: the shared NekMesh wing)
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/quality.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/occ/occ_backend.hpp"
#include "semimesh/surface/curve_discretisation.hpp"
#include "semimesh/surface/surface_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

namespace cad = semimesh::cad;
namespace mesh = semimesh::mesh;
namespace ho = semimesh::ho;
namespace surface = semimesh::surface;
using Vec3 = Eigen::Vector3d;

constexpr int kOrder = 4;
constexpr double kShell = 20.0;  // mm, the example's nearfield.thickness
constexpr int kBands = 9;        // bands 0..7, and 8 for everything within 12 sides

struct Pole {
  int surface = -1;
  int vertex = -1;
  Vec3 at;
};

/// The first surface with a degenerate curve in its loops, and that curve's vertex.
Pole find_pole(const cad::Model& model) {
  for (int s = 0; s < model.num_surfaces(); ++s)
    for (const cad::Loop& loop : model.loops(s))
      for (const cad::CurveUse& use : loop.uses)
        if (model.curve(use.curve).is_degenerate()) {
          const int v = model.curve_vertices(use.curve)[0];
          return {s, v, model.vertex(v).point};
        }
  throw std::runtime_error("no surface with a pole in this model");
}

/// Band of a triangle: how many of its longest sides its nearest vertex lies from the pole.
int band_of(const surface::SurfaceMesh& sm, const std::array<int, 3>& t, const Vec3& pole) {
  double side = 0.0, nearest = 1e300;
  for (int i = 0; i < 3; ++i) {
    side = std::max(side, (sm.points[t[(i + 1) % 3]] - sm.points[t[i]]).norm());
    nearest = std::min(nearest, (sm.points[t[i]] - pole).norm());
  }
  const double sides = nearest / side;
  if (sides <= 0.0) return 0;
  if (sides > 12.0) return -1;
  return std::min(kBands - 1, static_cast<int>(std::ceil(sides)));
}

/// One layer of prisms of thickness kShell on `triangles` of the pole's surface mesh, outward.
/// At the pole (no normal there) the skin moves along the mean normal of the pole's neighbours.
mesh::Mesh shell(const cad::Model& model, const Pole& pole, const surface::SurfaceMesh& sm,
                 const std::vector<std::array<int, 3>>& triangles, const Vec3& pole_normal) {
  const cad::Surface& s = model.surface(pole.surface);
  mesh::Mesh m(1);
  std::map<std::array<int, 3>, mesh::NodeId> merged;  // by origin: the pole's two images are one node
  const auto node = [&](int i) {
    const surface::NodeOrigin& o = sm.origin[i];
    const std::array<int, 3> key = o.vertex >= 0 ? std::array<int, 3>{0, o.vertex, 0}
                                   : o.on_boundary() ? std::array<int, 3>{1, o.curve, o.index}
                                                     : std::array<int, 3>{2, i, 0};
    if (auto found = merged.find(key); found != merged.end()) return found->second;
    mesh::CadAttachment a;
    if (o.vertex >= 0) a = {mesh::CadAttachment::Vertex, o.vertex, 0, 0};
    else if (o.on_boundary()) a = {mesh::CadAttachment::Curve, o.curve, o.t, 0};
    else a = {mesh::CadAttachment::Surface, pole.surface, sm.uv[i](0), sm.uv[i](1)};
    const Vec3 n = o.vertex == pole.vertex ? pole_normal : s.normal(sm.uv[i]);
    const mesh::NodeId body = m.add_node(sm.points[i], a);
    m.add_node(sm.points[i] + kShell * n);
    return merged[key] = body;
  };
  const int region = m.region_index("shell");
  for (const auto& t : triangles) {
    const mesh::NodeId a = node(t[0]), b = node(t[1]), c = node(t[2]);
    m.add_element(ho::Shape::Prism, {a, b, c, a + 1, b + 1, c + 1}, region);
    m.add_boundary_face("tip", ho::Shape::Triangle, {a, c, b});
  }
  return m;
}

struct BandFigures {
  double error = 0.0;                    // max geometric error, mm
  double shell_sj = 1.0, layers_sj = 1.0;  // min scaled Jacobian
};

double min_scaled_jacobian(const mesh::Mesh& m) {
  double worst = 1.0;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    worst = std::min(worst, ho::element_quality(m.elements()[e].shape, m.order(), m.node_set(),
                                                m.element_coordinates(e)).scaled_jacobian);
  return worst;
}

BandFigures measure(const mesh::Mesh& linear, const cad::Model& model, double reach) {
  ho::CurvingParams params;
  params.order = kOrder;
  params.pole_reach = reach;
  const mesh::Mesh curved = ho::curve_mesh(linear, model, params);
  std::vector<std::size_t> all(curved.elements().size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = e;
  const mesh::Mesh layers = ho::split_layers(curved, all, {6, 1.5});
  return {ho::geometric_error(curved, model, 1.0, 8).max_rel, min_scaled_jacobian(curved), min_scaled_jacobian(layers)};
}

void table(const cad::Model& model, const Pole& pole, double curvature_segments) {
  surface::SizeParams p;
  p.max_size = 500.0;
  p.min_size = 0.5;
  p.curvature_segments = curvature_segments;
  p.gradation = 1.2;
  p.le_size = p.te_size = 0.0;
  const surface::SizeField size(model, p);
  const surface::CurveMeshes curves = surface::discretise_all_curves(model, size);
  const surface::SurfaceMesh sm = surface::mesh_surface(model, pole.surface, curves, size);

  std::vector<std::vector<std::array<int, 3>>> bands(kBands);
  Vec3 pole_normal = Vec3::Zero();
  for (const auto& t : sm.triangles) {
    const int b = band_of(sm, t, pole.at);
    if (b >= 0) bands[b].push_back(t);
    for (int i : t)
      if (sm.origin[i].vertex != pole.vertex && (sm.points[i] - pole.at).norm() < 2.0 * size(pole.at))
        pole_normal += model.surface(pole.surface).normal(sm.uv[i]);
  }
  pole_normal.normalize();
  fmt::print("\nsizes near the pole {:.2f} mm ({} segments a radian of curvature), order {}, shell {} mm\n",
             size(pole.at), curvature_segments, kOrder, kShell);
  fmt::print("band (sides from the pole):      ");
  for (int b = 0; b < kBands; ++b) fmt::print(b + 1 < kBands ? "{:>9}" : "{:>9}", b + 1 < kBands ? std::to_string(b) : "8..12");
  fmt::print("\nprisms:                          ");
  for (const auto& band : bands) fmt::print("{:>9}", band.size());
  fmt::print("\n");
  for (double reach : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 8.0, 1e9}) {
    std::vector<BandFigures> f;
    for (const auto& band : bands) f.push_back(band.empty() ? BandFigures{} : measure(shell(model, pole, sm, band, pole_normal), model, reach));
    const std::string name = reach > 1e6 ? std::string("all") : fmt::format("{:g}", reach);
    fmt::print("reach {:>3}  max error (mm)       ", name);
    for (const auto& x : f) fmt::print("{:>9.1e}", x.error);
    fmt::print("\n           min scaled J shell   ");
    for (const auto& x : f) fmt::print("{:>9.3f}", x.shell_sj);
    fmt::print("\n           min scaled J layers  ");
    for (const auto& x : f) fmt::print("{:>9.3f}", x.layers_sj);
    fmt::print("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp";
  const auto model = semimesh::occ::load_occ(cad::Source{path, {}});
  const Pole pole = find_pole(*model);
  fmt::print("{}: pole of surface {} ('{}') at ({:.2f}, {:.2f}, {:.2f})\n", path, pole.surface,
             model->surface(pole.surface).name(), pole.at.x(), pole.at.y(), pole.at.z());
  for (double segments : {4.0, 8.0}) table(*model, pole, segments);
  return 0;
}
