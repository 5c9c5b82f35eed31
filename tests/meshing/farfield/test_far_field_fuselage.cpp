// The far field on a curved wall: the NACA 0012 wing on the analytic circular fuselage
// (naca.wall = cylinder, radius R = 1.5, axis along x through z = -R), its O-type shell and the far
// field meshing the fuselage in its parameters. Checked against the closed form of the cylinder.
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/o_shell.hpp"

#include "wing_case.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace semimesh::farfield {
namespace {

constexpr double kRadius = 1.5;

double off_the_cylinder(const Eigen::Vector3d& x) { return std::hypot(x.y(), x.z() + kRadius) - kRadius; }

struct FuselageCase {
  std::unique_ptr<cad::Model> model;
  FarField far;
  std::size_t prisms = 0;
};

// The wing 1 long on the fuselage, its box, coarse surface meshes.
nearfield::testing::WingCase wing_on_the_fuselage() {
  mock_cad::NacaWingParams wing;
  wing.span = 1.0;
  wing.fuselage = true;
  wing.wall_radius = kRadius;
  wing.box = {-2, -3, -5, 3, 3, 2};
  return nearfield::testing::wing_case(wing, /*max_size=*/0.3);
}

// The far field round a near field of `wall_layer` (0: none), box and wall sizes 1 (above R / 4:
// the wall's curvature caps the size).
FarField far_field_of(const nearfield::testing::WingCase& wc, nearfield::NearField nf, double wall_layer) {
  std::vector<int> box;
  for (const char* name : {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmin", "box_zmax"})
    box.push_back(*wc.model->find_surface(name));
  FarFieldParams params;
  params.box_size = 1.0;
  params.wall_size = 1.0;
  return build_far_field(*wc.model, std::move(nf), params, box, wc.roles.wall_surface, wall_layer);
}

nearfield::ShellParams shell_of(double thickness) {
  nearfield::ShellParams shell;
  shell.thickness = thickness;
  return shell;
}

FuselageCase fuselage_far_field() {
  nearfield::testing::WingCase wc = wing_on_the_fuselage();
  nearfield::NearField nf = nearfield::build_o_shell(*wc.model, wc.meshes, wc.roles, shell_of(0.03));
  FuselageCase c;
  c.prisms = nf.mesh.elements().size();
  c.far = far_field_of(wc, std::move(nf), 0.0);
  c.model = std::move(wc.model);
  return c;
}

TEST(FarFieldOnAFuselage, WallTrianglesLieOnTheCylinderFacingIntoItAndTurnAQuarterRadianAtMost) {
  const FuselageCase c = fuselage_far_field();
  const mesh::Mesh& m = c.far.mesh;
  const auto it = std::find(m.group_names().begin(), m.group_names().end(), "wall");
  ASSERT_NE(it, m.group_names().end());
  const auto wall_group = static_cast<std::uint16_t>(it - m.group_names().begin());
  int wall_triangles = 0;
  double longest = 0.0;
  for (const mesh::BoundaryFace& f : m.boundary_faces()) {
    if (f.group != wall_group || f.shape != ho::Shape::Triangle) continue;
    ++wall_triangles;
    const Eigen::Vector3d a = m.node(f.vertices[0]), b = m.node(f.vertices[1]), d = m.node(f.vertices[2]);
    for (const Eigen::Vector3d& x : {a, b, d}) EXPECT_NEAR(off_the_cylinder(x), 0.0, 1e-9) << x.transpose();
    // Out of the domain is into the fuselage: towards its axis.
    const Eigen::Vector3d centre = (a + b + d) / 3.0;
    const Eigen::Vector3d outward_radial = Eigen::Vector3d(0, centre.y(), centre.z() + kRadius).normalized();
    EXPECT_LT((b - a).cross(d - a).normalized().dot(outward_radial), -0.9) << centre.transpose();
    longest = std::max({longest, (b - a).norm(), (d - b).norm(), (a - d).norm()});
  }
  EXPECT_GT(wall_triangles, 100);
  // The chart is exact on a cylinder: edges stay near the curvature cap R / 4 (the annulus' own
  // Delaunay slack), far below wall_size = 1.
  EXPECT_LT(longest, 1.5 * kRadius / 4.0);
}

// Under a wall layer thin against the fuselage's radius (0.01 on R = 1.5, C-type) an edge turning a
// quarter radian would dip R (1 - cos 1/8) = 0.0117, more than the layer, below its straight top:
// the wall's edges turn at most sqrt(8 * 0.15 * 0.01 / R) = 0.089 radian, so they dip 0.15 of the
// layer at most (the annulus' Delaunay slack and the grading allowed: 2x; 1.8x measured), and the
// layer's prisms stand on them.
TEST(FarFieldOnAFuselage, AThinWallLayerRefinesTheWallUnderIt) {
  constexpr double kWallLayer = 0.01;
  const nearfield::testing::WingCase wc = wing_on_the_fuselage();
  const FarField far = far_field_of(
      wc, nearfield::build_c_shell(*wc.model, wc.meshes, wc.roles, shell_of(0.03), {}, kWallLayer), kWallLayer);
  const mesh::Mesh& m = far.mesh;
  const auto it = std::find(m.group_names().begin(), m.group_names().end(), "wall");
  ASSERT_NE(it, m.group_names().end());
  const auto wall_group = static_cast<std::uint16_t>(it - m.group_names().begin());
  double longest = 0.0;
  for (const mesh::BoundaryFace& f : m.boundary_faces())
    if (f.group == wall_group && f.shape == ho::Shape::Triangle)
      for (int k = 0; k < 3; ++k) longest = std::max(longest, (m.node(f.vertices[k]) - m.node(f.vertices[(k + 1) % 3])).norm());
  const double turn = std::sqrt(8 * 0.15 * kWallLayer / kRadius);
  EXPECT_GT(longest, 0.0);
  EXPECT_LT(longest, 2.0 * kRadius * turn) << "a quarter radian is " << kRadius / 4;
  EXPECT_GT(far.stats.tets, 0u);
}

TEST(FarFieldOnAFuselage, TetsArePositiveAndFillTheBoxAroundTheFuselage) {
  const FuselageCase c = fuselage_far_field();
  const mesh::Mesh& m = c.far.mesh;
  EXPECT_EQ(m.elements().size(), c.prisms + c.far.stats.tets);
  double tets = 0.0;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    if (m.elements()[e].shape != ho::Shape::Tetrahedron) continue;
    const auto x = m.element_coordinates(e);
    const double volume = (x.row(1) - x.row(0)).cross(x.row(2) - x.row(0)).dot(x.row(3) - x.row(0)) / 6.0;
    EXPECT_GT(volume, 0.0) << "tet " << e;
    tets += volume;
    // No tet reaches into the fuselage (its nodes on or outside the cylinder).
    for (int k = 0; k < 4; ++k) EXPECT_GT(off_the_cylinder(x.row(k).transpose()), -1e-9) << "tet " << e;
  }
  // The box less the fuselage's length in it; the wing with its layer (~0.15) and the gap of the
  // flat facets under the cylinder stay within the 1 % band (0.35).
  const double box = 5.0 * 6.0 * 7.0, fuselage = M_PI * kRadius * kRadius * 5.0;
  EXPECT_NEAR(tets, box - fuselage, 0.01 * fuselage);
}

}  // namespace
}  // namespace semimesh::farfield
