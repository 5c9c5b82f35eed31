// Model topology: a closed tetrahedron (each edge used once forward, once reversed) and the
// errors finalize() must raise on broken input.
#include "expect_error.hpp"
#include "shapes.hpp"

#include "semimesh/cad/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using semimesh::cad::CadError;
using semimesh::cad::CurveUse;
using semimesh::cad::Interval;
using semimesh::cad::Loop;
using semimesh::cad::Model;
using shapes::Line;
using shapes::Plane;
using shapes::Vec2;
using shapes::Vec3;

namespace {

const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0), kD(0, 0, 1);
enum Edge { AB, AC, AD, BC, BD, CD };

std::unique_ptr<Plane> triangle(int id, const Vec3& o, const Vec3& p1, const Vec3& p2) {
  return std::make_unique<Plane>(id, o, p1 - o, p2 - o, std::array<Interval, 2>{Interval{0, 1}, Interval{0, 1}},
                                 [](const Vec2& uv) { return uv.x() >= 0 && uv.y() >= 0 && uv.x() + uv.y() <= 1 + 1e-12; });
}

// Unit tetrahedron A B C D, solid inside. Each face's e1 x e2 points outward (into the fluid)
// and its loop runs counter-clockwise around that normal.
std::unique_ptr<Model> tetrahedron(std::vector<Loop> z0_loops = {Loop{{{AC, true}, {BC, false}, {AB, false}}}}) {
  auto m = std::make_unique<Model>("test");
  for (const Vec3& p : {kA, kB, kC, kD}) m->add_vertex(p);
  const std::pair<int, int> ends[] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const Vec3 pts[] = {kA, kB, kC, kD};
  for (int e = 0; e < 6; ++e)
    m->add_curve(std::make_unique<Line>(e, pts[ends[e].first], pts[ends[e].second]), ends[e].first, ends[e].second);
  m->add_surface(triangle(0, kA, kC, kB), std::move(z0_loops));                                // z = 0, normal -z
  m->add_surface(triangle(1, kA, kB, kD), {Loop{{{AB, true}, {BD, true}, {AD, false}}}});  // y = 0, normal -y
  m->add_surface(triangle(2, kA, kD, kC), {Loop{{{AD, true}, {CD, false}, {AC, false}}}});  // x = 0, normal -x
  m->add_surface(triangle(3, kB, kC, kD), {Loop{{{BC, true}, {CD, true}, {BD, false}}}});  // normal (1,1,1)
  return m;
}

}  // namespace

TEST(Model, ClosedTetrahedronTopology) {
  auto m = tetrahedron();
  m->finalize();
  EXPECT_TRUE(m->is_closed());
  EXPECT_EQ(m->num_vertices(), 4);
  EXPECT_EQ(m->num_curves(), 6);
  EXPECT_EQ(m->num_surfaces(), 4);
  for (int c = 0; c < 6; ++c) {
    const auto& uses = m->surfaces_of_curve(c);
    ASSERT_EQ(uses.size(), 2u) << "curve " << c;
    EXPECT_NE(uses[0].forward, uses[1].forward) << "curve " << c << " must be walked once each way";
  }
  auto at_a = m->curves_of_vertex(0);
  std::sort(at_a.begin(), at_a.end());
  EXPECT_EQ(at_a, (std::vector<int>{AB, AC, AD}));
  EXPECT_EQ(m->curve_vertices(CD), (std::array<int, 2>{2, 3}));
  EXPECT_TRUE(m->bbox().lo.isApprox(Vec3(0, 0, 0)));
  EXPECT_TRUE(m->bbox().hi.isApprox(Vec3(1, 1, 1)));
  EXPECT_EQ(m->find_surface("plane"), 0);
  EXPECT_FALSE(m->find_surface("nothing").has_value());
  EXPECT_TRUE(m->surface(3).normal(Vec2(0.2, 0.2)).isApprox(Vec3(1, 1, 1).normalized()));
}

TEST(Model, OpenSurfaceIsNotClosed) {
  auto m = std::make_unique<Model>("test");
  for (const Vec3& p : {kA, kB, kC}) m->add_vertex(p);
  m->add_curve(std::make_unique<Line>(0, kA, kB), 0, 1);
  m->add_curve(std::make_unique<Line>(1, kB, kC), 1, 2);
  m->add_curve(std::make_unique<Line>(2, kC, kA), 2, 0);
  m->add_surface(triangle(0, kA, kB, kC), {Loop{{{0, true}, {1, true}, {2, true}}}});
  m->finalize();
  EXPECT_FALSE(m->is_closed());
  EXPECT_EQ(m->surfaces_of_curve(1).size(), 1u);
}

TEST(Model, LoopThatDoesNotCloseIsRejected) {
  auto m = tetrahedron({Loop{{{AC, true}, {BC, false}}}});  // stops at B, never returns to A
  expect_cad_error([&] { m->finalize(); }, CadError::Kind::Geometry, "surface 0 ('plane') loop 0 is not closed");
}

TEST(Model, LoopWalkingACurveTheWrongWayIsRejected) {
  auto m = tetrahedron({Loop{{{AC, true}, {BC, true}, {AB, false}}}});
  expect_cad_error([&] { m->finalize(); }, CadError::Kind::Geometry, "is not closed");
}

TEST(Model, LoopNamingAMissingCurveIsRejected) {
  auto m = tetrahedron({Loop{{{AC, true}, {17, false}, {AB, false}}}});
  expect_cad_error([&] { m->finalize(); }, CadError::Kind::Geometry, "names curve 17");
}

TEST(Model, SurfaceWithoutLoopIsRejected) {
  auto m = tetrahedron({});
  expect_cad_error([&] { m->finalize(); }, CadError::Kind::Geometry, "surface 0 ('plane') has no loop");
  auto e = tetrahedron({Loop{}});
  expect_cad_error([&] { e->finalize(); }, CadError::Kind::Geometry, "loop 0 is empty");
}

TEST(Model, CurveNamingAMissingVertexIsRejected) {
  Model m("test");
  m.add_vertex(kA);
  m.add_curve(std::make_unique<Line>(0, kA, kB), 0, 9);
  expect_cad_error([&] { m.finalize(); }, CadError::Kind::Geometry, "names vertex 9");
}

TEST(Model, EntityAddedWithWrongIdIsRejected) {
  Model m("test");
  m.add_vertex(kA);
  expect_cad_error([&] { m.add_curve(std::make_unique<Line>(3, kA, kB), 0, 0); }, CadError::Kind::Geometry,
                   "curve added with id 3, expected 0");
  expect_cad_error([&] { m.add_surface(triangle(2, kA, kB, kC), {}); }, CadError::Kind::Geometry,
                   "surface added with id 2, expected 0");
}

TEST(Model, LookupOfMissingEntityNamesIt) {
  auto m = tetrahedron();
  m->finalize();
  expect_cad_error([&] { m->curve(6); }, CadError::Kind::Geometry, "no curve with id 6 (model has 6)");
  expect_cad_error([&] { m->surface(-1); }, CadError::Kind::Geometry, "no surface with id -1");
  expect_cad_error([&] { m->vertex(4); }, CadError::Kind::Geometry, "no vertex with id 4");
}
