// The analytic twin of test_step_shells.cpp: the C- and H-type near fields on the NACA wing with a
// rounded tip (naca.tip = round), whose blunt trailing-edge base is capped by a half disc running
// into the tip's arc tangentially, as on the NekMesh STEP wing. Proven here in closed form:
//  (a) at the base's two flat corners (tip_te_upper, tip_te_lower) the wake sweeps two prisms per
//      station instead of a hex, and nowhere else (the flat tip's base has square corners: none);
//  (b) the lift onto the root strip fades out at the body's lowest vertex off the wall (z = span,
//      where the skins meet the tip), below the tip's crown: no node above it moves.
// Every near-field element is valid at order 1.
#include "semimesh/cad/model.hpp"
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/h_shell.hpp"
#include "semimesh/surface/cad_roles.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include "wing_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

namespace semimesh::nearfield {
namespace {

using cad::Vec3;

constexpr double kSpan = 1.5;

struct Wing {
  std::unique_ptr<cad::Model> model;
  surface::CadRoles roles;
  surface::SurfaceMeshes meshes;
};

// NACA 0012 on a unit chord, the coarse sizes of test_h_shell.cpp but for min_size: the tip's
// trailing-edge arc (radius 0.00126) needs at least two segments, else one base quad holds both
// flat corners and its split can relieve only one of them (as min_size <= 0.0018 is needed anyway
// under a 0.05 shell at order >= 2). The H-type meshes the base with structured quads.
Wing mesh_wing(bool round_tip, bool sharp, bool h_type) {
  mock_cad::NacaWingParams p;
  p.span = kSpan;
  p.sharp_te = sharp;
  p.round_tip = round_tip;
  Wing w;
  w.model = mock_cad::make_naca_wing(p);
  w.roles = surface::detect_cad_roles(*w.model);
  surface::SizeParams size;
  size.max_size = 0.4;
  size.min_size = 0.0015;
  size.curvature_segments = 2.0;
  size.le_size = 0.04;
  size.te_size = 0.04;
  surface::ModelMeshOptions options;
  if (h_type && w.roles.te_base) options.structured_surfaces.insert(*w.roles.te_base);
  w.meshes = surface::mesh_model_surfaces(*w.model, surface::SizeField(*w.model, size), options);
  return w;
}

BodyRoles body_roles(const Wing& w) { return {w.roles.body, w.roles.wall}; }

ShellParams shell() {
  ShellParams p;
  p.thickness = 0.05;
  return p;
}

constexpr double kWallThickness = 0.04;

WakeParams wake_behind(const Wing& w) {
  WakeParams wake;
  if (w.roles.te_base) wake.te_base = w.model->surface(*w.roles.te_base).name();
  wake.length = 1.0;
  wake.layers = 6;
  return wake;
}

NearField h_shell(const Wing& w) {
  return build_h_shell(*w.model, w.meshes, body_roles(w), shell(), JunctionParams{}, kWallThickness, wake_behind(w),
                       w.model->bbox(), {});
}

int region_id(const mesh::Mesh& m, const std::string& name) {
  return static_cast<int>(std::find(m.region_names().begin(), m.region_names().end(), name) - m.region_names().begin());
}

int vertex_named(const cad::Model& model, const std::string& name) {
  for (int v = 0; v < model.num_vertices(); ++v)
    if (model.vertex(v).name == name) return v;
  return -1;
}

TEST(RoundTipShells, RolesFindTheCappedBaseAndTheRoundTip) {
  mock_cad::NacaWingParams p;
  p.span = kSpan;
  p.round_tip = true;
  Wing w;
  w.model = mock_cad::make_naca_wing(p);
  w.roles = surface::detect_cad_roles(*w.model);
  ASSERT_TRUE(w.roles.te_base.has_value());
  EXPECT_EQ(w.model->surface(*w.roles.te_base).name(), "te_base");
  ASSERT_EQ(w.roles.tip.size(), 1u);
  EXPECT_EQ(w.model->surface(w.roles.tip.front()).name(), "tip");
  EXPECT_NEAR(w.roles.span, kSpan + 0.06, 1e-3);  // the crown: span + max y_t of 0012
}

// (a) Each flat corner's quad is swept as two prisms per station, split from the corner: 2 corners
// x 2 prisms x layers, and the prisms of the first station stand on the two corner vertices.
TEST(RoundTipShells, HTypeWakeSweepsTwoPrismsAtEachFlatCornerOfTheBase) {
  for (bool round_tip : {true, false}) {
    const Wing w = mesh_wing(round_tip, false, true);
    const WakeParams wake = wake_behind(w);
    const NearField field = h_shell(w);
    const mesh::Mesh& m = field.mesh;
    const std::string what = round_tip ? "rounded tip" : "flat tip";
    EXPECT_EQ(testing::invalid_elements(m), 0) << what;
    EXPECT_GT(field.wake.hexes, 0) << what;
    EXPECT_GE(field.wake.gap, wake.gap - 1e-9) << what;
    const int wake_region = region_id(m, "wake");
    const int corners[2] = {vertex_named(*w.model, "tip_te_upper"), vertex_named(*w.model, "tip_te_lower")};
    int prisms = 0, at_corner[2] = {0, 0};
    for (const mesh::Element& e : m.elements()) {
      if (e.region != wake_region || e.shape != ho::Shape::Prism) continue;
      ++prisms;
      for (int k = 0; k < 6; ++k) {
        const mesh::CadAttachment& a = m.cad_attachment(e.vertices[k]);
        for (int c = 0; c < 2; ++c)
          if (a.kind == mesh::CadAttachment::Vertex && a.entity == corners[c]) ++at_corner[c];
      }
    }
    // The flat tip's base is a trapezoid with square corners: hexes only.
    EXPECT_EQ(prisms, round_tip ? 2 * 2 * wake.layers : 0) << what;
    EXPECT_EQ(at_corner[0], round_tip ? 2 : 0) << what << ": prisms at tip_te_upper";
    EXPECT_EQ(at_corner[1], round_tip ? 2 : 0) << what << ": prisms at tip_te_lower";
  }
}

// (b) The tip's crown stands 0.06 chord above the skins' top (z = span, the lowest vertices off
// the wall: the tip's leading-edge pole and the base's flat corners). The lift onto the root strip
// fades out there: every near-field node above z = span (on the tip, or on the base's cap) is a node
// of the surface mesh where the mesher put it, while the skins' nodes below are lifted. A lift that
// faded out at the crown instead would raise the tip's nodes by up to strip * 0.06 / 1.56.
TEST(RoundTipShells, LiftOntoTheRootStripFadesOutAtTheLowestVertexOffTheWall) {
  for (bool h_type : {false, true}) {
    const Wing w = mesh_wing(true, false, h_type);
    const NearField field = h_type ? h_shell(w)
                                   : build_c_shell(*w.model, w.meshes, body_roles(w), shell(), JunctionParams{}, kWallThickness);
    const std::string what = h_type ? "H-type" : "C-type";
    EXPECT_EQ(testing::invalid_elements(field.mesh), 0) << what;
    std::vector<Vec3> meshed;
    for (int s : w.roles.body)
      for (const Vec3& x : w.meshes.surfaces.at(s).points) meshed.push_back(x);
    auto moved = [&](const Vec3& x) {
      double nearest = 1e300;
      for (const Vec3& y : meshed) nearest = std::min(nearest, (x - y).norm());
      return nearest;
    };
    const int tip = w.roles.tip.front(), base = *w.roles.te_base;
    int above = 0, lifted = 0;
    for (mesh::NodeId v = 0; v < static_cast<mesh::NodeId>(field.mesh.num_nodes()); ++v) {
      const mesh::CadAttachment& a = field.mesh.cad_attachment(v);
      if (a.kind != mesh::CadAttachment::Surface) continue;
      const Vec3 x = field.mesh.node(v);
      if ((a.entity == tip || a.entity == base) && x.z() > kSpan + 1e-9) {
        ++above;
        EXPECT_LT(moved(x), 1e-12) << what << ": node on the tip or the base's cap at " << x.transpose() << " moved";
      } else if (a.entity != tip && a.entity != base && x.z() > 0.2 && x.z() < 0.5 * kSpan && moved(x) > 1e-6) {
        ++lifted;
      }
    }
    EXPECT_GT(above, 20) << what;
    EXPECT_GT(lifted, 10) << what << ": the skins' nodes below are lifted";
  }
}

// The sharp trailing edge closes the rounded tip to a second pole: the H-type's cracked layer and
// its wake sheet stay valid, with no base and so no prism in the wake.
TEST(RoundTipShells, SharpTrailingEdgeClosedByAPoleGivesAValidHType) {
  const Wing w = mesh_wing(true, true, true);
  ASSERT_FALSE(w.roles.te_base.has_value());
  WakeParams wake = wake_behind(w);
  const NearField field = build_h_shell(*w.model, w.meshes, body_roles(w), shell(), JunctionParams{}, kWallThickness, wake,
                                        w.model->bbox(), {});
  EXPECT_EQ(testing::invalid_elements(field.mesh), 0);
  EXPECT_GT(field.wake.hexes, 0);
}

}  // namespace
}  // namespace semimesh::nearfield
