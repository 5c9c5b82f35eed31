// The C- and H-type near fields on the shared NekMesh STEP wing through the occ backend (skipped
// when ../shared/testdata/cad is absent): a skin that is one face around the leading edge (a root
// vertex with no curve leaving the wall), a revolved tip whose pole and trailing-edge corners stand
// below its crown, and a trailing-edge base at 10 degrees of incidence to the wake's direction.
// Every element of the near field is valid at order 1; the junction runs along the whole root
// loop, and the H-type's wake hexes leave the base along +x.
#include "semimesh/cad/model.hpp"
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/h_shell.hpp"
#include "semimesh/occ/occ_backend.hpp"
#include "semimesh/surface/cad_roles.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include "wing_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

namespace semimesh::nearfield {
namespace {

std::string nekmesh_wing() { return std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp"; }

struct StepWing {
  std::unique_ptr<cad::Model> model;
  surface::CadRoles roles;
  surface::SurfaceMeshes meshes;
};

// The example's sizes (mm). The H-type meshes the trailing-edge base with structured quads.
StepWing mesh_step_wing(bool h_type) {
  StepWing w;
  w.model = occ::load_occ(cad::Source{nekmesh_wing(), {}});
  w.roles = surface::detect_cad_roles(*w.model);
  surface::SizeParams p;
  p.max_size = 500.0;
  p.min_size = 2.0;
  p.curvature_segments = 4.0;
  p.gradation = 1.2;
  p.le_curves = {};
  p.te_curves = {};
  surface::ModelMeshOptions options;
  if (h_type && w.roles.te_base) options.structured_surfaces.insert(*w.roles.te_base);
  w.meshes = surface::mesh_model_surfaces(*w.model, surface::SizeField(*w.model, p), options);
  return w;
}

BodyRoles body_roles(const StepWing& w) { return {w.roles.body, w.roles.wall}; }

ShellParams shell() {
  ShellParams p;
  p.thickness = 20.0;
  return p;
}

#define SKIP_WITHOUT_FILE()                     \
  if (!std::filesystem::exists(nekmesh_wing())) \
  GTEST_SKIP() << nekmesh_wing() << " not found (see shared/testdata/cad/README.md)"

TEST(StepShells, CTypeJunctionRunsAroundTheOneFaceSkinAndTheRevolvedTipStays) {
  SKIP_WITHOUT_FILE();
  const StepWing w = mesh_step_wing(false);
  ASSERT_TRUE(w.roles.te_base.has_value());
  const NearField field = build_c_shell(*w.model, w.meshes, body_roles(w), shell(), JunctionParams{}, 20.0);
  EXPECT_EQ(testing::invalid_elements(field.mesh), 0);
  EXPECT_EQ(field.junction_hexes, static_cast<int>(field.footprint.size()));
  // The revolved tip is not lifted: its nodes keep their place on the CAD.
  const cad::Surface& tip = w.model->surface(w.roles.tip.front());
  double farthest = 0.0;
  for (mesh::NodeId v = 0; v < static_cast<mesh::NodeId>(field.mesh.num_nodes()); ++v) {
    const mesh::CadAttachment& a = field.mesh.cad_attachment(v);
    if (a.kind == mesh::CadAttachment::Surface && a.entity == w.roles.tip.front())
      farthest = std::max(farthest, (tip.point(cad::Vec2(a.u, a.v)) - field.mesh.node(v)).norm());
  }
  EXPECT_LT(farthest, 1e-6);
}

TEST(StepShells, HTypeWakeLeavesTheInclinedBaseAlongTheFreestream) {
  SKIP_WITHOUT_FILE();
  const StepWing w = mesh_step_wing(true);
  WakeParams wake;
  wake.te_base = w.model->surface(*w.roles.te_base).name();
  wake.length = 1000.0;
  wake.gap = 100.0;
  const NearField field =
      build_h_shell(*w.model, w.meshes, body_roles(w), shell(), JunctionParams{}, 20.0, wake, w.model->bbox(), {});
  EXPECT_EQ(testing::invalid_elements(field.mesh), 0);
  EXPECT_GT(field.wake.hexes, 0);
  EXPECT_EQ(field.wake.hexes % wake.layers, 0);
  EXPECT_GE(field.wake.gap, wake.gap - 1e-9);
  EXPECT_GT(field.junction_hexes, 0);
  // The base is a rectangle capped by a half disc: at its two top corners the side meets the arc
  // tangentially, and a hex there would have a vanishing Jacobian once curved (2 invalid at order 4).
  // Each corner quad is swept as two prisms instead, split from the corner.
  const mesh::Mesh& m = field.mesh;
  const int wake_region = static_cast<int>(std::find(m.region_names().begin(), m.region_names().end(), "wake") -
                                           m.region_names().begin());
  int prisms = 0;
  for (const mesh::Element& e : m.elements())
    if (e.region == wake_region && e.shape == ho::Shape::Prism) ++prisms;
  EXPECT_EQ(prisms, 2 * 2 * wake.layers);
}

}  // namespace
}  // namespace semimesh::nearfield
