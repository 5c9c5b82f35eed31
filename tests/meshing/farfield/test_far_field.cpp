// The far field around a synthetic near field: a unit cube standing on the wall, its skin made of
// triangles and quads, inside the analytic model's far-field box.
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <map>
#include <set>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;
using mesh::NodeId;
using Key = std::array<NodeId, 3>;

Key sorted(NodeId a, NodeId b, NodeId c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

double tet_volume(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

constexpr std::array<double, 6> kBox = {-3, -3, 0, 4, 3, 3};  // xmin, ymin, zmin, xmax, ymax, zmax

std::unique_ptr<cad::Model> box_model() {
  mock_cad::NacaWingParams p;
  p.span = 1.0;
  p.box = kBox;
  return mock_cad::make_naca_wing(p);
}

std::vector<int> box_surfaces(const cad::Model& model) {
  std::vector<int> ids;
  for (const char* name : {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}) ids.push_back(*model.find_surface(name));
  return ids;
}

// Skin of the cube [-h,h]^2 x [0, top] with n x n cells per face: top and +x faces as quads, the
// other sides split into triangles; footprint = the bottom square, counter-clockwise seen from +z.
struct CubeSkin {
  nearfield::NearField nf;
  std::set<Key> skin_triangles;
  int quads = 0;
};

CubeSkin cube_skin(double h, double top, int n) {
  CubeSkin cube;
  std::map<std::array<long, 3>, NodeId> ids;  // dedupe points shared by faces
  auto node = [&](const Vector3d& x) {
    const std::array<long, 3> key = {std::lround(x.x() * 1e6), std::lround(x.y() * 1e6), std::lround(x.z() * 1e6)};
    auto [it, added] = ids.try_emplace(key, 0);
    if (added) it->second = cube.nf.mesh.add_node(x);
    return it->second;
  };
  struct Face {
    Vector3d origin, a, b;  // a x b points out of the cube
    bool quads;
  };
  const double t = top;
  const std::vector<Face> faces = {
      {{-h, -h, t}, {2 * h, 0, 0}, {0, 2 * h, 0}, true},   // top
      {{h, -h, 0}, {0, 2 * h, 0}, {0, 0, t}, true},        // +x
      {{-h, -h, 0}, {0, 0, t}, {0, 2 * h, 0}, false},      // -x
      {{-h, h, 0}, {0, 0, t}, {2 * h, 0, 0}, false},       // +y
      {{-h, -h, 0}, {2 * h, 0, 0}, {0, 0, t}, false},      // -y
  };
  for (const Face& f : faces)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        auto p = [&](int di, int dj) { return node(f.origin + f.a * double(i + di) / n + f.b * double(j + dj) / n); };
        const NodeId v0 = p(0, 0), v1 = p(1, 0), v2 = p(1, 1), v3 = p(0, 1);
        if (f.quads) {
          cube.nf.skin.push_back({{v0, v1, v2, v3}, 4});
          ++cube.quads;
        } else {
          cube.nf.skin.push_back({{v0, v1, v2, 0}, 3});
          cube.nf.skin.push_back({{v0, v2, v3, 0}, 3});
          cube.skin_triangles.insert(sorted(v0, v1, v2));
          cube.skin_triangles.insert(sorted(v0, v2, v3));
        }
      }
  const std::array<Vector3d, 4> corners = {Vector3d(-h, -h, 0), Vector3d(h, -h, 0), Vector3d(h, h, 0), Vector3d(-h, h, 0)};
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < n; ++i)
      cube.nf.footprint.push_back(node(corners[side] + (corners[(side + 1) % 4] - corners[side]) * double(i) / n));
  return cube;
}

class FarFieldAroundCube : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = box_model().release();
    cube_ = new CubeSkin(cube_skin(0.5, 1.0, 3));
    for (NodeId i = 0; i < cube_->nf.mesh.num_nodes(); ++i) skin_points_.push_back(cube_->nf.mesh.node(i));
    FarFieldParams params;
    params.box_size = 1.0;
    params.wall_size = 0.6;
    FarField far = build_far_field(*model_, cube_->nf, params, box_surfaces(*model_), *model_->find_surface("wall"));
    mesh_ = new mesh::Mesh(std::move(far.mesh));
    stats_ = far.stats;
  }
  static void TearDownTestSuite() {
    delete mesh_;
    delete cube_;
    delete model_;
  }
  static const mesh::Mesh& mesh() { return *mesh_; }

  static mesh::Mesh* mesh_;
  static cad::Model* model_;
  static CubeSkin* cube_;
  static std::vector<Vector3d> skin_points_;
  static FarFieldStats stats_;
};
cad::Model* FarFieldAroundCube::model_ = nullptr;
CubeSkin* FarFieldAroundCube::cube_ = nullptr;
std::vector<Vector3d> FarFieldAroundCube::skin_points_;
FarFieldStats FarFieldAroundCube::stats_;
mesh::Mesh* FarFieldAroundCube::mesh_ = nullptr;

TEST_F(FarFieldAroundCube, CountsAndSkinNodesUntouched) {
  EXPECT_EQ(stats_.pyramids, cube_->quads);
  EXPECT_EQ(stats_.pyramids, 18);
  EXPECT_GT(stats_.tets, 100);
  EXPECT_GT(stats_.wall_triangles, 0);
  EXPECT_GT(stats_.box_triangles, 0);
  int tets = 0, pyramids = 0;
  for (const auto& e : mesh().elements()) (e.shape == ho::Shape::Tetrahedron ? tets : pyramids) += 1;
  EXPECT_EQ(tets, stats_.tets);
  EXPECT_EQ(pyramids, stats_.pyramids);
  for (NodeId i = 0; i < skin_points_.size(); ++i) EXPECT_EQ(mesh().node(i), skin_points_[i]) << "node " << i;
}

// The cube's structured faces and the box's planes tie TetGen's predicates: its mesh of the untied
// boundary is the one taken (the tests of this suite check that mesh on the true points).
TEST_F(FarFieldAroundCube, TetGensMeshOfTheUntiedBoundaryIsTaken) { EXPECT_TRUE(stats_.tetgen_untied); }

TEST_F(FarFieldAroundCube, ElementsHavePositiveVolumeAndFillTheBoxMinusTheCube) {
  double volume = 0.0;
  for (std::size_t e = 0; e < mesh().elements().size(); ++e) {
    const auto& el = mesh().elements()[e];
    const auto& v = el.vertices;
    auto x = [&](int k) { return mesh().node(v[k]); };
    if (el.shape == ho::Shape::Tetrahedron) {
      const double vol = tet_volume(x(0), x(1), x(2), x(3));
      EXPECT_GT(vol, 1e-9) << "tet " << e;
      volume += vol;
    } else {
      ASSERT_EQ(el.shape, ho::Shape::Pyramid);
      // planar base: the pyramid is exactly the two tets over the base's diagonal
      const double a = tet_volume(x(0), x(1), x(2), x(4)), b = tet_volume(x(0), x(2), x(3), x(4));
      EXPECT_GT(a, 0.0) << "pyramid " << e;
      EXPECT_GT(b, 0.0) << "pyramid " << e;
      volume += a + b;
    }
  }
  const double box = (kBox[3] - kBox[0]) * (kBox[4] - kBox[1]) * (kBox[5] - kBox[2]);
  EXPECT_NEAR(volume, box - 1.0, 1e-10 * box);
}

TEST_F(FarFieldAroundCube, SkinAndPyramidSidesAreFacesOfExactlyOneTetAndTheBoundaryIsClosed) {
  std::map<Key, int> tet_faces;
  for (const auto& el : mesh().elements()) {
    if (el.shape != ho::Shape::Tetrahedron) continue;
    const auto& v = el.vertices;
    for (const auto& f : ho::faces(ho::Shape::Tetrahedron)) ++tet_faces[sorted(v[f[0]], v[f[1]], v[f[2]])];
  }
  std::set<Key> boundary = cube_->skin_triangles;
  for (const Key& k : cube_->skin_triangles) EXPECT_EQ(tet_faces[k], 1);
  for (const auto& el : mesh().elements()) {
    if (el.shape != ho::Shape::Pyramid) continue;
    for (int k = 0; k < 4; ++k) {
      const Key side = sorted(el.vertices[k], el.vertices[(k + 1) % 4], el.vertices[4]);
      EXPECT_EQ(tet_faces[side], 1);
      boundary.insert(side);
    }
  }
  const int wall = static_cast<int>(std::find(mesh().group_names().begin(), mesh().group_names().end(), "wall") -
                                    mesh().group_names().begin());
  int wall_faces = 0, box_faces = 0;
  for (const auto& bf : mesh().boundary_faces()) {
    const Key k = sorted(bf.vertices[0], bf.vertices[1], bf.vertices[2]);
    EXPECT_EQ(tet_faces[k], 1);
    boundary.insert(k);
    (bf.group == wall ? wall_faces : box_faces) += 1;
  }
  EXPECT_EQ(wall_faces, stats_.wall_triangles);
  EXPECT_EQ(box_faces, stats_.box_triangles);
  for (const auto& [face, count] : tet_faces) {
    EXPECT_LE(count, 2);
    if (count == 1) {
      EXPECT_TRUE(boundary.count(face)) << "a tet face lies on no boundary: the boundary is not closed";
    }
  }
}

TEST_F(FarFieldAroundCube, BoundaryFacesPointOutOfTheDomainAndCoverWallAndBox) {
  const auto& names = mesh().group_names();
  double wall_area = 0.0, box_area = 0.0;
  const Vector3d centre(0.5 * (kBox[0] + kBox[3]), 0.5 * (kBox[1] + kBox[4]), 0.5 * (kBox[2] + kBox[5]));
  for (const auto& bf : mesh().boundary_faces()) {
    const Vector3d a = mesh().node(bf.vertices[0]), b = mesh().node(bf.vertices[1]), c = mesh().node(bf.vertices[2]);
    const Vector3d n = 0.5 * (b - a).cross(c - a);
    if (names[bf.group] == "wall") {
      EXPECT_LT(n.z(), 0.0);
      EXPECT_NEAR(a.z(), 0.0, 1e-12);
      wall_area += n.norm();
    } else {
      ASSERT_EQ(names[bf.group], "farfield");
      EXPECT_GT(n.dot((a + b + c) / 3.0 - centre), 0.0);
      box_area += n.norm();
    }
  }
  const double dx = kBox[3] - kBox[0], dy = kBox[4] - kBox[1], dz = kBox[5] - kBox[2];
  EXPECT_NEAR(wall_area, dx * dy - 1.0, 1e-10);
  EXPECT_NEAR(box_area, dx * dy + 2 * dz * (dx + dy), 1e-10);
}

TEST_F(FarFieldAroundCube, WallAndBoxNodesCarryTheirCadAttachment) {
  const int wall = *model_->find_surface("wall");
  std::set<NodeId> footprint(cube_->nf.footprint.begin(), cube_->nf.footprint.end());
  const auto& names = mesh().group_names();
  for (const auto& bf : mesh().boundary_faces())
    for (int k = 0; k < 3; ++k) {
      const NodeId id = bf.vertices[k];
      if (footprint.count(id)) continue;
      const mesh::CadAttachment& cad = mesh().cad_attachment(id);
      EXPECT_NE(cad.kind, mesh::CadAttachment::None) << "node " << id;
      if (names[bf.group] == "wall" && cad.kind == mesh::CadAttachment::Surface) {
        EXPECT_EQ(cad.entity, wall);
        // the analytic wall is parametrised by (x, y)
        EXPECT_NEAR(cad.u, mesh().node(id).x(), 1e-9);
        EXPECT_NEAR(cad.v, mesh().node(id).y(), 1e-9);
      }
    }
}

// Work beside TetGen's process: it sees every element but the tetrahedra and the layer stacks the
// far field returns, runs until TetGen has answered, and changes nothing in the mesh built, also
// when it throws.
TEST_F(FarFieldAroundCube, WorkBesideTetgenSeesTheMeshSoFarAndChangesNothing) {
  FarFieldParams params;
  params.box_size = 1.0;
  params.wall_size = 0.6;
  const int wall = *model_->find_surface("wall");
  std::size_t elements = 0, tets = 1;
  std::vector<std::size_t> stack_elements;
  bool stopped = false;
  const FarField with = build_far_field(
      *model_, cube_->nf, params, box_surfaces(*model_), wall, 0.0, {},
      [&](const mesh::Mesh& so_far, const std::vector<nearfield::LayerStack>& stacks, const std::atomic<bool>& stop) {
        elements = so_far.elements().size();
        for (const nearfield::LayerStack& s : stacks) stack_elements.push_back(s.element);
        tets = static_cast<std::size_t>(std::count_if(so_far.elements().begin(), so_far.elements().end(),
                                                      [](const mesh::Element& e) { return e.shape == ho::Shape::Tetrahedron; }));
        while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        stopped = true;
      });
  EXPECT_TRUE(stopped);
  EXPECT_EQ(tets, 0u);
  EXPECT_EQ(elements, static_cast<std::size_t>(stats_.pyramids));
  std::vector<std::size_t> returned;
  for (const nearfield::LayerStack& s : with.stacks) returned.push_back(s.element);
  EXPECT_EQ(stack_elements, returned);
  const FarField thrown = build_far_field(*model_, cube_->nf, params, box_surfaces(*model_), wall, 0.0, {},
                                          [](const mesh::Mesh&, const std::vector<nearfield::LayerStack>&,
                                             const std::atomic<bool>&) { throw std::runtime_error("x"); });
  for (const mesh::Mesh* m : {&with.mesh, &thrown.mesh}) {
    ASSERT_EQ(m->nodes(), mesh().nodes());
    ASSERT_EQ(m->elements().size(), mesh().elements().size());
    for (std::size_t e = 0; e < m->elements().size(); ++e) ASSERT_EQ(m->element_nodes(e), mesh().element_nodes(e)) << e;
    ASSERT_EQ(m->boundary_faces().size(), mesh().boundary_faces().size());
  }
}

// The pyramids' apexes (one per skin quad) and the interior points are found on every thread: the
// far field is the same on one thread as on all of them, node for node.
TEST_F(FarFieldAroundCube, SameMeshOnOneThreadAndOnFour) {
  FarFieldParams params;
  params.box_size = 1.0;
  params.wall_size = 0.6;
  const int wall = *model_->find_surface("wall");
  omp_set_num_threads(1);
  const FarField one = build_far_field(*model_, cube_->nf, params, box_surfaces(*model_), wall);
  omp_set_num_threads(4);
  const FarField four = build_far_field(*model_, cube_->nf, params, box_surfaces(*model_), wall);
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_GT(stats_.pyramids, 0);
  ASSERT_EQ(one.mesh.nodes(), four.mesh.nodes());
  ASSERT_EQ(one.mesh.elements().size(), four.mesh.elements().size());
  for (std::size_t e = 0; e < one.mesh.elements().size(); ++e)
    ASSERT_EQ(one.mesh.element_nodes(e), four.mesh.element_nodes(e)) << e;
}

TEST(FarField, RejectsBadParametersAndANonPlanarWall) {
  const auto model = box_model();
  FarFieldParams bad;
  bad.growth = 0.9;
  CubeSkin cube = cube_skin(0.5, 1.0, 2);
  const int wall = *model->find_surface("wall");
  EXPECT_THROW(build_far_field(*model, cube.nf, bad, box_surfaces(*model), wall), FarFieldError);
  EXPECT_THROW(build_far_field(*model, cube.nf, {}, box_surfaces(*model), *model->find_surface("upper")), FarFieldError);
  EXPECT_THROW(build_far_field(*model, cube.nf, {}, box_surfaces(*model), 999), FarFieldError);
}

TEST(FarField, FootprintOutsideTheBoxIsReported) {
  const auto model = box_model();
  CubeSkin cube = cube_skin(3.5, 1.0, 2);  // wider than the box in y
  try {
    build_far_field(*model, cube.nf, {}, box_surfaces(*model), *model->find_surface("wall"));
    FAIL() << "expected FarFieldError";
  } catch (const FarFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("footprint"), std::string::npos) << e.what();
  }
}

TEST(FarField, SkinThroughTheBoxIsReportedAsTetGenFailure) {
  const auto model = box_model();
  CubeSkin cube = cube_skin(0.5, 3.5, 2);  // pokes through the box top at z = 3
  try {
    build_far_field(*model, cube.nf, {}, box_surfaces(*model), *model->find_surface("wall"));
    FAIL() << "expected FarFieldError";
  } catch (const FarFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("TetGen"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("crosses boundary triangle"), std::string::npos) << e.what();
    // Which parts cross: the skin and the box (not the skin itself: no hint of a thin body).
    EXPECT_NE(std::string(e.what()).find("(the near field's outer skin)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(the far field's outer boundary)"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("meets itself"), std::string::npos) << e.what();
  }
}

// A boundary point closer to its neighbour than TetGen's merge distance (1e-8 of the boundary's
// bounding-box diagonal, 9.7e-8 here): TetGen would merge the two and fail (at 10^7 elements it
// crashed); the far field refuses the boundary first and says why. The -x face's centre moves along
// its diagonal to 1e-9 from the corner: the face's triangles keep their orientation.
TEST(FarField, EdgeShorterThanTetGensMergeDistanceIsReported) {
  const auto model = box_model();
  CubeSkin cube = cube_skin(0.5, 1.0, 2);
  const Vector3d corner(-0.5, -0.5, 0.0), centre(-0.5, 0.0, 0.5);
  for (NodeId i = 0; i < cube.nf.mesh.num_nodes(); ++i)
    if ((cube.nf.mesh.node(i) - centre).norm() < 1e-12) cube.nf.mesh.place_node(i, corner + 1e-9 * (centre - corner).normalized());
  try {
    build_far_field(*model, cube.nf, {}, box_surfaces(*model), *model->find_surface("wall"));
    FAIL() << "expected FarFieldError";
  } catch (const FarFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("shorter than TetGen's merge distance"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace semimesh::farfield
