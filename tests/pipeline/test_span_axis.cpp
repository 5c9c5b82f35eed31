// Spans in any axis: the OCC-built NACA wing on its wall in its box, once as built (span along z)
// and once turned by an exact quarter turn about x (span along y, the ONERA M6's frame), meshed by
// the whole pipeline with the C-type near field (wing layer, root junction, wall layer): the y-span
// near field is the z-span one turned, node for node.
#include "semimesh/occ/occ_backend.hpp"
#include "semimesh/pipeline/pipeline.hpp"
#include "temp_path.hpp"

#include <BRepBuilderAPI_Transform.hxx>
#include <BRepTools.hxx>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace semimesh::pipeline {
namespace {

namespace fs = std::filesystem;

// The quarter turn about x taking z to y: (x, y, z) -> (x, z, -y). Written with exact 0 and +-1
// entries so the turned coordinates are exactly the permuted ones (no cos(pi/2) round-off).
Eigen::Vector3d turned(const Eigen::Vector3d& p) { return {p.x(), p.z(), -p.y()}; }

gp_Trsf quarter_turn() {
  gp_Trsf t;
  t.SetValues(1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0);
  return t;
}

std::string wing_file(const fs::path& dir, const std::string& name, bool turn) {
  mock_cad::NacaWingParams wing;
  wing.span = 1.0;
  wing.box = {-3.0, -3.0, 0.0, 4.0, 3.0, 3.0};
  TopoDS_Shape shape = occ::make_naca_wing_shape(wing);
  if (turn) shape = BRepBuilderAPI_Transform(shape, quarter_turn(), /*copy=*/true).Shape();
  const std::string path = (dir / name).string();
  EXPECT_TRUE(BRepTools::Write(shape, path.c_str()));
  return path;
}

RunResult mesh_of(const std::string& source, const fs::path& dir) {
  Config c = parse_config(R"(
[geometry]
backend = "occ"
source = "wing.brep"
[nearfield]
topology = "C"
thickness = 0.06
[wall_layer]
thickness = 0.04
layers = 2
[boundary_layer]
layers = 2
[sizing]
max_size = 1.0
min_size = 0.035
curvature_segments = 2
le_size = 0
te_size = 0
[farfield]
box_size = 2.0
wall_size = 1.0
[highorder]
order = 2
[output]
formats = ["msh41"]
)", "span.toml");
  c.geometry.source = source;
  c.output.directory = dir.string();
  Progress quiet;
  return run(c, quiet);
}

// The nodes of the elements of `region`, turned or not, keyed by their coordinates rounded to
// `step`, sorted.
std::vector<std::array<long long, 3>> region_nodes(const mesh::Mesh& m, const std::string& region, bool turn, double step) {
  const auto index = std::find(m.region_names().begin(), m.region_names().end(), region) - m.region_names().begin();
  std::vector<std::array<long long, 3>> out;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    if (m.elements()[e].region != index) continue;
    const Eigen::MatrixX3d x = m.element_coordinates(e);
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      const Eigen::Vector3d p = turn ? turned(x.row(i).transpose()) : Eigen::Vector3d(x.row(i).transpose());
      out.push_back({std::llround(p.x() / step), std::llround(p.y() / step), std::llround(p.z() / step)});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SpanAxis, AWingAlongYMeshesAsTheWingAlongZTurned) {
  const fs::path dir = semimesh::test::temp_path("span_axis");
  fs::create_directories(dir);
  const RunResult along_z = mesh_of(wing_file(dir, "z.brep", false), dir / "z");
  const RunResult along_y = mesh_of(wing_file(dir, "y.brep", true), dir / "y");
  for (const RunResult* r : {&along_z, &along_y}) {
    EXPECT_TRUE(r->checks_passed());
    EXPECT_EQ(r->validity.invalid, 0u);
    EXPECT_GT(r->elements_by_type.at("prism"), 0u);
  }
  // The near field (surface meshes, shell, root junction, curving, split) is the same mesh turned,
  // node for node (every node of every wing-layer and junction element, to 1e-9 chord).
  for (const char* region : {"wing_layer", "junction"})
    EXPECT_EQ(along_y.elements_by_region.at(region), along_z.elements_by_region.at(region)) << region;
  EXPECT_EQ(along_y.boundary_faces_by_group.at("wing"), along_z.boundary_faces_by_group.at("wing"));
  EXPECT_EQ(along_y.boundary_faces_by_group.at("farfield"), along_z.boundary_faces_by_group.at("farfield"));
  for (const char* region : {"wing_layer", "junction"}) {
    const auto z_nodes = region_nodes(along_z.mesh, region, true, 1e-9);
    const auto y_nodes = region_nodes(along_y.mesh, region, false, 1e-9);
    ASSERT_EQ(y_nodes.size(), z_nodes.size()) << region;
    EXPECT_GT(z_nodes.size(), 0u) << region;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < z_nodes.size(); ++i) differ += z_nodes[i] != y_nodes[i];
    EXPECT_EQ(differ, 0u) << "of " << z_nodes.size() << " " << region << " element nodes";
    EXPECT_NEAR(along_y.validity.min_scaled_jacobian_by_region.at(region),
                along_z.validity.min_scaled_jacobian_by_region.at(region), 1e-9);
  }
  const auto y_layer = region_nodes(along_y.mesh, "wing_layer", false, 1e-9);
  // The far field is TetGen's in both, not the same tets: its point order follows the axes (and the
  // wall's annulus is triangulated in a frame built from x or y), so only its measure is the same.
  EXPECT_NEAR(along_y.volume.expected_volume(), along_z.volume.expected_volume(), 1e-9 * along_z.volume.expected_volume());
  const double tets_z = along_z.elements_by_type.at("tetrahedron"), tets_y = along_y.elements_by_type.at("tetrahedron");
  EXPECT_NEAR(tets_y, tets_z, 0.05 * tets_z);
  // And the wing really stands along y: its layer reaches y = 1 (the span) and no z beyond the box's.
  double top = 0.0;
  for (const auto& k : y_layer) top = std::max(top, k[1] * 1e-9);
  EXPECT_GT(top, 1.0) << "the layer's top is above the tip at y = 1";
  EXPECT_LT(top, 1.1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace semimesh::pipeline
