// The C-type near field end to end, stage by stage (surface mesh, C-shell, far field with the wall
// layer, curving, splitting of the layer stacks): conformity, volume (element integral against
// the boundary flux and against box - body), proven validity, elements by region.
#include "semimesh/backends/builtin.hpp"
#include "semimesh/checks/conformity.hpp"
#include "semimesh/checks/validity.hpp"
#include "semimesh/checks/volume.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/pipeline/split_stacks.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "highorder/mesh/same_entities.hpp"
#include "semimesh/mesh/compact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <utility>

namespace semimesh {
namespace {

struct Case {
  std::string backend = "naca";
  std::string code = "0012";
  std::string te = "blunt";
  double taper = 1.0, sweep = 0.0;
};

struct Built {
  std::unique_ptr<cad::Model> model;
  int junction_hexes = 0;
  farfield::FarField far;  ///< the whole linear mesh and its layer stacks
  std::vector<int> box;
};

constexpr double kBox[6] = {-3.0, -3.0, 0.0, 4.0, 3.0, 3.0};

Built build(const Case& c, double thickness, double wall_thickness) {
  Built b;
  cad::Source source;
  source.params.set("naca.code", c.code);
  source.params.set("naca.span", "1");
  source.params.set("naca.te", c.te);
  source.params.set("naca.taper", std::to_string(c.taper));
  source.params.set("naca.sweep", std::to_string(c.sweep));
  source.params.set("naca.box", "-3,-3,0,4,3,3");
  b.model = backends::default_registry().load(c.backend, source);
  surface::SizeParams size;
  size.max_size = 1.0;
  size.min_size = 0.02;
  size.curvature_segments = 2;
  size.le_size = 0.06;
  size.te_size = 0.03;
  const surface::SizeField field(*b.model, size);
  const surface::SurfaceMeshes meshes = surface::mesh_model_surfaces(*b.model, field);
  nearfield::BodyRoles roles;
  for (const std::string name : {"upper", "lower", "te_base", "tip"})
    if (auto s = b.model->find_surface(name)) roles.body_surfaces.push_back(*s);
  roles.wall_surface = *b.model->find_surface("wall");
  for (const std::string name : {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"})
    b.box.push_back(*b.model->find_surface(name));
  nearfield::ShellParams shell;
  shell.thickness = thickness;
  nearfield::NearField near =
      nearfield::build_c_shell(*b.model, meshes, roles, shell, nearfield::JunctionParams{}, wall_thickness);
  b.junction_hexes = near.junction_hexes;
  farfield::FarFieldParams far;
  far.box_size = 1.0;
  far.wall_size = 0.6;
  b.far = farfield::build_far_field(*b.model, std::move(near), far, b.box, roles.wall_surface, wall_thickness);
  return b;
}

std::map<std::string, int> elements_by_region(const mesh::Mesh& m) {
  std::map<std::string, int> count;
  for (const auto& el : m.elements()) ++count[m.region_names()[el.region]];
  return count;
}

// Box minus the wing: the wing volume as span x section area, the section area by the trapezoid
// rule on the NACA thickness formula (blunt TE: open at x = 1), scaled by taper.
double expected_volume(const Case& c) {
  const double t = std::stod(c.code.substr(2)) / 100.0;
  const int n = 200000;
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) / n;
    const double yt = 5 * t *
                      (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                       (c.te == "sharp" ? 0.1036 : 0.1015) * x * x * x * x);
    area += 2 * yt / n;
  }
  const double chord_area_factor = (1 + c.taper + c.taper * c.taper) / 3.0;  // mean of chord^2 over the span
  return (kBox[3] - kBox[0]) * (kBox[4] - kBox[1]) * (kBox[5] - kBox[2]) - area * chord_area_factor;
}

void expect_sound(const mesh::Mesh& m, const Case& c, double volume_tolerance) {
  const checks::ConformityResult conformity = checks::check_conformity(m);
  EXPECT_TRUE(conformity.ok()) << (conformity.problems.empty() ? "" : conformity.problems.front().describe(m));
  const checks::ValidityResult validity = checks::check_validity(m);
  EXPECT_EQ(validity.invalid, 0u) << "min scaled Jacobian " << validity.min_scaled_jacobian;
  const checks::MeshVolume volume = checks::mesh_volume(m);
  EXPECT_LT(volume.boundary_relative_error(), 1e-9);
  EXPECT_NEAR(volume.element_volume, expected_volume(c), volume_tolerance);
}

TEST(CTypeEndToEnd, LinearMeshOnTheAnalyticWing) {
  const Case c;
  const Built b = build(c, 0.05, 0.04);
  const mesh::Mesh& m = b.far.mesh;
  const auto regions = elements_by_region(m);
  EXPECT_EQ(regions.at("junction"), b.junction_hexes);
  EXPECT_EQ(regions.at("wall_layer"), b.far.stats.wall_layer_prisms);
  EXPECT_GT(regions.at("wing_layer"), 100);
  EXPECT_EQ(regions.at("farfield"), b.far.stats.tets + b.far.stats.pyramids);
  EXPECT_EQ(b.far.stacks.size(),
            static_cast<std::size_t>(regions.at("junction") + regions.at("wall_layer") + regions.at("wing_layer")));
  expect_sound(m, c, 2e-3);
}

// The split that adopts the coarse mesh's entities (the pipeline's: its tetrahedra come over
// without a lookup) keeps those only the split elements used, unused; renumbered
// (without_unreferenced_nodes) it is the canonical split's mesh, entity for entity.
TEST(CTypeEndToEnd, AdoptedEntitiesRenumberToTheCanonicalSplit) {
  const Case c;
  const Built b = build(c, 0.05, 0.04);
  ho::CurvingParams curving;
  curving.order = 4;  // the copied tetrahedra have an interior node
  const mesh::Mesh curved = ho::curve_mesh(b.far.mesh, *b.model, curving);
  const pipeline::FamilySplit wing{{3, 1.5}, {}}, wall{{2, 2.0}, {}};
  const pipeline::StackSplit canonical = pipeline::split_stacks(curved, b.far.stacks, wing, wall);
  pipeline::StackSplit adopted =
      pipeline::split_stacks(curved, b.far.stacks, wing, wall, {}, false, ho::SplitEntities::Adopted);
  ASSERT_EQ(adopted.mesh.elements().size(), canonical.mesh.elements().size());
  for (std::size_t e = 0; e < canonical.mesh.elements().size(); ++e)
    ASSERT_EQ(adopted.mesh.element_nodes(e), canonical.mesh.element_nodes(e)) << "element " << e;
  EXPECT_GT(adopted.mesh.edges().size(), canonical.mesh.edges().size());  // the coarse ones only split ones used
  EXPECT_GT(adopted.mesh.faces().size(), canonical.mesh.faces().size());
  test::expect_same_entities(mesh::without_unreferenced_nodes(std::move(adopted.mesh)),
                             mesh::without_unreferenced_nodes(canonical.mesh));
}

TEST(CTypeEndToEnd, CurvedAndSplitInBothDirections) {
  const Case c;
  const Built b = build(c, 0.05, 0.04);
  ho::CurvingParams curving;
  curving.order = 2;
  const mesh::Mesh curved = ho::curve_mesh(b.far.mesh, *b.model, curving);
  const int n_wing = 3, n_wall = 2;
  const pipeline::StackSplit split =
      pipeline::split_stacks(curved, b.far.stacks, {{n_wing, 1.5}, {}}, {{n_wall, 2.0}, {}});
  const auto before = elements_by_region(b.far.mesh), after = elements_by_region(split.mesh);
  EXPECT_EQ(after.at("junction"), before.at("junction") * n_wing * n_wall);
  EXPECT_EQ(after.at("wing_layer"), before.at("wing_layer") * n_wing);
  EXPECT_EQ(after.at("wall_layer"), before.at("wall_layer") * n_wall);
  EXPECT_EQ(after.at("farfield"), before.at("farfield"));
  expect_sound(split.mesh, c, 2e-3);
}

}  // namespace
}  // namespace semimesh

namespace semimesh {
namespace {

class CTypeVariants : public ::testing::TestWithParam<Case> {};

TEST_P(CTypeVariants, ConformingValidMeshWithTheRightVolume) {
  const Case c = GetParam();
  if (c.backend == "occ" && !backends::default_registry().available("occ"))
    GTEST_SKIP() << "no OCC backend in this build";
  const Built b = build(c, 0.05, 0.04);
  const auto regions = elements_by_region(b.far.mesh);
  EXPECT_EQ(regions.at("junction"), b.junction_hexes);
  EXPECT_EQ(regions.at("wall_layer"), b.far.stats.wall_layer_prisms);
  expect_sound(b.far.mesh, c, 3e-3);
}

INSTANTIATE_TEST_SUITE_P(Wings, CTypeVariants,
                         ::testing::Values(Case{"naca", "0012", "sharp"}, Case{"naca", "2412", "blunt"},
                                           Case{"naca", "2412", "sharp"}, Case{"naca", "0012", "blunt", 0.5, 30.0},
                                           Case{"occ", "0012", "blunt"}, Case{"occ", "2412", "sharp"},
                                           Case{"occ", "0012", "sharp", 0.5, 30.0}));

// At order 3, every face a junction piece shares with a wing- or wall-layer piece is one face
// entity (the very same high-order nodes): W-H strips N_wing per hex, L-H strips N_wall per hex.
TEST(CTypeEndToEnd, JunctionPiecesShareTheirFacesWithTheSplitPrismsNodeForNode) {
  const Case c;
  const Built b = build(c, 0.05, 0.04);
  ho::CurvingParams curving;
  curving.order = 3;
  const mesh::Mesh curved = ho::curve_mesh(b.far.mesh, *b.model, curving);
  const int n_wing = 3, n_wall = 4;
  const pipeline::StackSplit split =
      pipeline::split_stacks(curved, b.far.stacks, {{n_wing, 2.0}, {}}, {{n_wall, 1.5}, {}});
  const mesh::Mesh& m = split.mesh;
  const auto region = [&](const std::string& name) {
    return static_cast<int>(std::find(m.region_names().begin(), m.region_names().end(), name) -
                            m.region_names().begin());
  };
  const int junction = region("junction"), wing = region("wing_layer"), wall = region("wall_layer");
  std::map<std::uint32_t, std::vector<int>> users;  // face -> regions of its elements
  for (const auto& el : m.elements())
    for (std::size_t f = 0; f < ho::faces(el.shape).size(); ++f) users[el.faces[f]].push_back(el.region);
  int with_wing = 0, with_wall = 0;
  for (const auto& [face, regions] : users) {
    if (regions.size() != 2 || std::count(regions.begin(), regions.end(), junction) != 1) continue;
    with_wing += std::count(regions.begin(), regions.end(), wing) > 0;
    with_wall += std::count(regions.begin(), regions.end(), wall) > 0;
  }
  EXPECT_EQ(with_wing, b.junction_hexes * n_wing);
  EXPECT_EQ(with_wall, b.junction_hexes * n_wall);
  expect_sound(m, c, 2e-3);
}

}  // namespace
}  // namespace semimesh

namespace semimesh {
namespace {

// The OCC-built wing (B-splines) curved at order 2 and split in both directions: the junction's
// quads on the wing and the wall are curved on the OCC faces like the prisms' triangles.
TEST(CTypeEndToEnd, OccWingCurvedAndSplit) {
  if (!backends::default_registry().available("occ")) GTEST_SKIP() << "no OCC backend in this build";
  const Case c{"occ", "2412", "blunt"};
  const Built b = build(c, 0.05, 0.04);
  ho::CurvingParams curving;
  curving.order = 2;
  const mesh::Mesh curved = ho::curve_mesh(b.far.mesh, *b.model, curving);
  const pipeline::StackSplit split = pipeline::split_stacks(curved, b.far.stacks, {{3, 1.5}, {}}, {{2, 2.0}, {}});
  EXPECT_EQ(elements_by_region(split.mesh).at("junction"), b.junction_hexes * 3 * 2);
  expect_sound(split.mesh, c, 3e-3);
}

}  // namespace
}  // namespace semimesh
