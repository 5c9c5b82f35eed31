// An OccSurface classified by several threads at once, as the curve stage does: every answer must
// be the one a single thread gets. OCC's face classifier keeps a mutable "current item" in its
// sequences of wires, so unguarded concurrent use read the wrong wire's polygon (a wrong answer)
// or walked off the end of the sequence (the curve stage's intermittent SIGSEGV): each thread now
// has its own. Surfaces of revolution and extrusion, evaluated by each thread on its own copy,
// give the bits the face's own surface gives one thread.
#include "occ_surface.hpp"
#include "occ_test_support.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace semimesh::occ::test {
namespace {

// A 10 x 10 square with a 4 x 4 array of round holes, every face a B-spline (as CAD tools export
// them): 17 wires, each exact classification walks all of them.
TopoDS_Face square_with_holes() {
  const gp_Pln plane(gp::XOY());
  BRepBuilderAPI_MakeFace face(plane, 0.0, 10.0, 0.0, 10.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const gp_Circ circle(gp_Ax2(gp_Pnt(1.5 + 2.3 * i, 1.5 + 2.3 * j, 0.0), gp::DZ()), 0.6);
      const TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)).Wire();
      face.Add(TopoDS::Wire(hole.Reversed()));
    }
  BRepBuilderAPI_NurbsConvert nurbs(face.Face());
  for (TopExp_Explorer f(nurbs.Shape(), TopAbs_FACE); f.More(); f.Next()) return TopoDS::Face(f.Current());
  return {};
}

// How many of `rounds` passes over `points` queries, made by 4 threads at once and out of step,
// `agrees(p)` says disagree with the one-thread answer for point p.
template <class Agrees>
int disagreements_across_threads(std::size_t points, int rounds, Agrees agrees) {
  constexpr int kThreads = 4;
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < rounds; ++round)
        for (std::size_t k = 0; k < points; ++k)
          if (!agrees((k * (t + 1) + round) % points)) ++wrong;
    });
  for (std::thread& t : threads) t.join();
  return wrong.load();
}

TEST(OccThreads, ExactClassificationOfAFaceWithHolesAgreesAcrossThreads) {
  const OccSurface surface(0, "holes", square_with_holes());
  ASSERT_EQ(surface.kind(), cad::SurfaceKind::BSpline);
  // Points all over the square, many on or near the holes' rims.
  constexpr int kSide = 60;
  std::vector<cad::Vec2> points;
  const auto box = surface.bounds();
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j)
      points.emplace_back(box[0].lo + box[0].length() * (i + 0.5) / kSide,
                          box[1].lo + box[1].length() * (j + 0.5) / kSide);
  std::vector<char> expected;
  for (const cad::Vec2& uv : points) expected.push_back(surface.contains_exactly(uv) ? 1 : 0);
  int inside = 0;
  for (char e : expected) inside += e;
  ASSERT_GT(inside, 0);
  ASSERT_LT(inside, static_cast<int>(points.size()));

  EXPECT_EQ(disagreements_across_threads(points.size(), 8, [&](std::size_t p) {
              return (surface.contains_exactly(points[p]) ? 1 : 0) == expected[p];
            }),
            0);
}

TEST(OccThreads, RevolutionAndExtrusionEvaluateToTheSharedSurfacesBitsOnEveryThread) {
  const std::string path = testdata("nektar_3d_bl_wing_naca0012.stp");
  if (!exists(path)) GTEST_SKIP() << "test CAD file " << path << " not found";
  const auto model = load_occ(cad::Source{path, {}});
  EXPECT_TRUE(model->thread_safe()) << "the wing's revolved tip and extruded skin no longer serialise the stages";
  int checked = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) {
    const auto& surface = dynamic_cast<const OccSurface&>(model->surface(s));
    if (surface.kind() != cad::SurfaceKind::Revolution && surface.kind() != cad::SurfaceKind::Extrusion) continue;
    ASSERT_TRUE(surface.has_mutable_evaluator());
    constexpr int kSide = 40;
    std::vector<cad::Vec2> points;
    const auto box = surface.bounds();
    for (int i = 0; i <= kSide; ++i)
      for (int j = 0; j <= kSide; ++j)
        points.emplace_back(box[0].lo + box[0].length() * i / kSide, box[1].lo + box[1].length() * j / kSide);
    std::vector<cad::SurfaceDerivatives> expected;
    for (const cad::Vec2& uv : points) expected.push_back(surface.derivatives_shared(uv));
    const auto same = [](const cad::SurfaceDerivatives& a, const cad::SurfaceDerivatives& b) {
      return a.p == b.p && a.du == b.du && a.dv == b.dv && a.duu == b.duu && a.duv == b.duv && a.dvv == b.dvv;
    };
    EXPECT_EQ(disagreements_across_threads(points.size(), 4,
                                           [&](std::size_t p) { return same(surface.derivatives(points[p]), expected[p]); }),
              0)
        << surface.name();
    ++checked;
  }
  EXPECT_EQ(checked, 2) << "the tip (revolution) and the skin (extrusion)";
}

}  // namespace
}  // namespace semimesh::occ::test
