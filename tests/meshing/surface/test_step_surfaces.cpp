// The two shared third-party STEP wings meshed surface by surface through the occ backend: the
// NekMesh wing's revolved tip (a periodic face with a pole, the face this mesher used to refuse)
// and the ONERA M6 (sliver faces at the tip TE). Every face meshes, the meshes conform along
// every curve, and no triangle faces against its surface's normal.
#include "semimesh/surface/model_surfaces.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace semimesh::surface {
namespace {

struct StepCase {
  const char* file;
  double max_size, min_size;  // model units (mm)
};

// Longest edge / size field at its midpoint: the refinement splits above 1.3 (split_factor), a
// longer edge is one it could not split.
constexpr double kMaxEdgeOverSize = 2.5;

class StepSurfaces : public ::testing::TestWithParam<StepCase> {};

TEST_P(StepSurfaces, EveryFaceMeshesConformingAndFacingTheFluid) {
  const std::string path = std::string(SEMIMESH_TESTDATA_DIR) + "/cad/" + GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "test CAD file " << path << " not found (see shared/testdata/cad/README.md)";
  const auto model = occ::load_occ(cad::Source{path, {}});
  SizeParams p;
  p.max_size = GetParam().max_size;
  p.min_size = GetParam().min_size;
  p.gradation = 1.3;
  p.le_curves = {};
  p.te_curves = {};
  const SizeField size(*model, p);
  const SurfaceMeshes meshes = mesh_model_surfaces(*model, size);
  EXPECT_TRUE(check_conformity(*model, meshes).empty());
  for (const SurfaceMesh& m : meshes.surfaces) {
    const cad::Surface& face = model->surface(m.surface);
    EXPECT_FALSE(m.triangles.empty()) << cad::surface_label(*model, m.surface);
    int folded = 0;
    for (const auto& t : m.triangles) {
      const Vec2 uv = (m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0;
      const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
      folded += n.dot(face.normal(uv)) <= 0.0 ? 1 : 0;
    }
    EXPECT_EQ(folded, 0) << cad::surface_label(*model, m.surface) << " (" << cad::to_string(face.kind()) << ")";
    // Edges at the size field's length: the revolved tip's (u an angle on a radius of ~70 mm, v a
    // length) reached 6 times it while its parameters were triangulated unscaled.
    double worst = 0.0;
    for (const auto& t : m.triangles)
      for (int e = 0; e < 3; ++e) {
        const Vec3 &a = m.points[t[e]], &b = m.points[t[(e + 1) % 3]];
        worst = std::max(worst, (b - a).norm() / size(0.5 * (a + b)));
      }
    EXPECT_LT(worst, kMaxEdgeOverSize) << cad::surface_label(*model, m.surface) << " (" << cad::to_string(face.kind()) << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, StepSurfaces,
                         ::testing::Values(StepCase{"nektar_3d_bl_wing_naca0012.stp", 200.0, 10.0},
                                           StepCase{"onera_m6_sharp_te.stp", 100.0, 5.0}),
                         [](const auto& info) { return info.index == 0 ? std::string("NektarWing") : std::string("OneraM6"); });

}  // namespace
}  // namespace semimesh::surface
