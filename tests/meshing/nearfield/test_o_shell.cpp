// The O-type shell on the analytic NACA wings: validity, the wall, the closed skin, the thickness,
// conformity, and the reduction/error paths.
#include "semimesh/cad/model.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "wing_case.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>

namespace semimesh::nearfield {
namespace {

using cad::Vec3;
using mesh::NodeId;

using testing::naca;
using testing::wing_case;
using testing::WingCase;

bool is_body_surface(const WingCase& c, int s) {
  return std::count(c.roles.body_surfaces.begin(), c.roles.body_surfaces.end(), s) > 0;
}

// Smallest distance from x to the body's CAD surfaces (points inside the trimmed faces only).
double distance_to_body(const WingCase& c, const Vec3& x) {
  double best = 1e300;
  for (int s : c.roles.body_surfaces) {
    const auto p = c.model->surface(s).project(x);
    if (p.inside) best = std::min(best, p.distance);
  }
  return best;
}

// All the properties the far field and the later stages rely on, checked independently.
void expect_sound_shell(const WingCase& c, const NearField& f, const ShellParams& params) {
  const mesh::Mesh& m = f.mesh;
  ASSERT_EQ(m.order(), 1);
  ASSERT_EQ(f.element_surface.size(), m.elements().size());
  ASSERT_GT(m.elements().size(), 0u);

  // Every prism: positive Jacobian at its 6 vertices (triple products) and certified over the element.
  int invalid = 0, not_certified = 0;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    ASSERT_EQ(m.elements()[e].shape, ho::Shape::Prism);
    const Eigen::MatrixX3d x = m.element_coordinates(e);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const Eigen::Vector3d up = x.row(i + 3) - x.row(i);
      const double bottom = (x.row(j) - x.row(i)).cross(x.row(k) - x.row(i)).dot(up);
      const double top = (x.row(j + 3) - x.row(i + 3)).cross(x.row(k + 3) - x.row(i + 3)).dot(up);
      invalid += !(bottom > 0.0) || !(top > 0.0);
    }
    not_certified += !ho::certify_jacobian(ho::Shape::Prism, 1, ho::NodeSet::Equispaced, x).valid;
    EXPECT_TRUE(is_body_surface(c, f.element_surface[e]));
  }
  EXPECT_EQ(invalid, 0);
  EXPECT_EQ(not_certified, 0);

  // Body nodes (vertices 0,1,2) lie on the CAD entity they are attached to.
  std::set<NodeId> body_nodes, outer_nodes;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    for (int i = 0; i < 6; ++i) (i < 3 ? body_nodes : outer_nodes).insert(m.elements()[e].vertices[i]);
  for (NodeId v : body_nodes) {
    const auto& a = m.cad_attachment(v);
    Vec3 on_cad;
    switch (a.kind) {
      case mesh::CadAttachment::Vertex: on_cad = c.model->vertex(a.entity).point; break;
      case mesh::CadAttachment::Curve: on_cad = c.model->curve(a.entity).point(a.u); break;
      case mesh::CadAttachment::Surface:
        EXPECT_TRUE(is_body_surface(c, a.entity));
        on_cad = c.model->surface(a.entity).point({a.u, a.v});
        break;
      default: ADD_FAILURE() << "body node " << v << " has no CAD attachment"; continue;
    }
    EXPECT_LT((on_cad - m.node(v)).norm(), 1e-9) << "body node " << v;
  }

  // Thickness: each offset at distance in [min, max] from its body node, the range within what was
  // asked, and the offset no closer to the body's CAD than half the smallest thickness.
  EXPECT_LE(f.thickness_max, params.thickness * (1 + 1e-9));
  EXPECT_GE(f.thickness_min, params.min_thickness_fraction * params.thickness * (1 - 1e-9));
  EXPECT_LE(f.thickness_min, f.thickness_max);
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    for (int i = 0; i < 3; ++i) {
      const double d = (m.node(m.elements()[e].vertices[i + 3]) - m.node(m.elements()[e].vertices[i])).norm();
      EXPECT_GE(d, f.thickness_min * (1 - 1e-9));
      EXPECT_LE(d, f.thickness_max * (1 + 1e-9));
    }
  for (NodeId v : outer_nodes) EXPECT_GE(distance_to_body(c, m.node(v)), 0.5 * f.thickness_min) << "offset node " << v;

  // Boundary groups: "wing" faces point into the body (against the CAD normal), "wall" quads lie on
  // z = 0 and point to -z.
  const auto& groups = m.group_names();
  const int wing = static_cast<int>(std::find(groups.begin(), groups.end(), "wing") - groups.begin());
  const int wall = static_cast<int>(std::find(groups.begin(), groups.end(), "wall") - groups.begin());
  ASSERT_LT(wing, static_cast<int>(groups.size()));
  ASSERT_LT(wall, static_cast<int>(groups.size()));
  std::size_t wing_faces = 0, wall_faces = 0;
  for (const auto& b : m.boundary_faces()) {
    if (b.group == wing) {
      ++wing_faces;
      const Vec3 p0 = m.node(b.vertices[0]), p1 = m.node(b.vertices[1]), p2 = m.node(b.vertices[2]);
      const Vec3 centre = (p0 + p1 + p2) / 3.0;
      int nearest = -1;
      double nearest_distance = 1e300;
      cad::Vec2 uv;
      for (int s : c.roles.body_surfaces) {
        const auto p = c.model->surface(s).project(centre);
        if (p.inside && p.distance < nearest_distance) nearest = s, nearest_distance = p.distance, uv = p.uv;
      }
      ASSERT_GE(nearest, 0);
      EXPECT_LT((p1 - p0).cross(p2 - p0).dot(c.model->surface(nearest).normal(uv)), 0.0);
    } else if (b.group == wall) {
      ++wall_faces;
      ASSERT_EQ(b.shape, ho::Shape::Quadrilateral);
      for (int i = 0; i < 4; ++i) EXPECT_LT(std::abs(m.node(b.vertices[i]).z()), 1e-12);
      const Vec3 n = (m.node(b.vertices[2]) - m.node(b.vertices[0])).cross(m.node(b.vertices[3]) - m.node(b.vertices[1]));
      EXPECT_LT(n.z(), 0.0);
    }
  }
  EXPECT_EQ(wing_faces, m.elements().size());
  EXPECT_GT(wall_faces, 0u);

  // Skin: closed together with the footprint. Each directed skin edge is used once; its reverse is
  // used by another skin face, except along the footprint, which no skin face crosses back.
  std::map<std::pair<NodeId, NodeId>, int> directed;
  for (const auto& s : f.skin) {
    ASSERT_EQ(s.count, 3);
    for (int i = 0; i < 3; ++i) ++directed[{s.nodes[i], s.nodes[(i + 1) % 3]}];
  }
  std::set<std::pair<NodeId, NodeId>> footprint_edges;
  ASSERT_GE(f.footprint.size(), 3u);
  for (std::size_t i = 0; i < f.footprint.size(); ++i)
    footprint_edges.insert({f.footprint[i], f.footprint[(i + 1) % f.footprint.size()]});
  EXPECT_EQ(footprint_edges.size(), wall_faces);
  int unmatched = 0;
  for (const auto& [edge, uses] : directed) {
    EXPECT_EQ(uses, 1);
    const bool has_reverse = directed.count({edge.second, edge.first}) > 0;
    unmatched += has_reverse == (footprint_edges.count(edge) > 0);
  }
  EXPECT_EQ(unmatched, 0);
  // The skin faces point out of the near field: away from the body, same side as the offset.
  for (std::size_t e = 0; e < f.skin.size(); ++e) {
    const auto& s = f.skin[e];
    const Vec3 n = (m.node(s.nodes[1]) - m.node(s.nodes[0])).cross(m.node(s.nodes[2]) - m.node(s.nodes[0]));
    const auto& el = m.elements()[e];
    const Vec3 offset = m.node(el.vertices[3]) + m.node(el.vertices[4]) + m.node(el.vertices[5]) -
                        m.node(el.vertices[0]) - m.node(el.vertices[1]) - m.node(el.vertices[2]);
    EXPECT_GT(n.dot(offset), 0.0) << "skin face " << e;
  }
  // Footprint: on the wall, counter-clockwise seen from +z (positive signed area in xy).
  double twice_area = 0.0;
  for (std::size_t i = 0; i < f.footprint.size(); ++i) {
    const Vec3 a = m.node(f.footprint[i]), b = m.node(f.footprint[(i + 1) % f.footprint.size()]);
    EXPECT_LT(std::abs(a.z()), 1e-12);
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_GT(twice_area, 0.0);

  // Conformity: every face entity is used by at most two prisms, and the faces used by one are
  // exactly the wing, wall and skin faces.
  std::map<std::uint32_t, int> face_uses;
  for (const auto& el : m.elements())
    for (int i = 0; i < 5; ++i) ++face_uses[el.faces[i]];
  std::size_t once = 0;
  for (const auto& [face, uses] : face_uses) {
    EXPECT_LE(uses, 2);
    once += uses == 1;
  }
  EXPECT_EQ(once, wing_faces + wall_faces + f.skin.size());
}

NearField timed_shell(const WingCase& c, const ShellParams& params, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  NearField f = build_o_shell(*c.model, c.meshes, c.roles, params);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << label << ": " << f.mesh.elements().size() << " prisms in " << seconds << " s, thickness ["
            << f.thickness_min << ", " << f.thickness_max << "], " << f.warnings.size() << " warnings\n";
  for (const auto& w : f.warnings) std::cout << "  warning: " << w.message << "\n";
  return f;
}

TEST(OShell, BluntNaca0012) {
  const WingCase c = wing_case(naca("0012", false));
  ShellParams params;
  const NearField f = timed_shell(c, params, "blunt 0012");
  expect_sound_shell(c, f, params);
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_NEAR(f.thickness_max, params.thickness, 1e-12);
}

TEST(OShell, SharpNaca0012) {
  const WingCase c = wing_case(naca("0012", true));
  ShellParams params;
  const NearField f = timed_shell(c, params, "sharp 0012");
  expect_sound_shell(c, f, params);
}

TEST(OShell, TaperedSweptNaca2412) {
  const WingCase c = wing_case(naca("2412", false, 0.5, 30.0));
  ShellParams params;
  params.thickness = 0.03;
  const NearField f = timed_shell(c, params, "tapered swept 2412");
  expect_sound_shell(c, f, params);
}

// A thin, strongly cambered section (NACA 9206) has a concave lower surface, radius of curvature
// about 0.25 chord near x = 0.15; a layer thicker than that would fold there and must be thinned
// locally, with a warning naming the place.
TEST(OShell, ConcaveRegionIsThinnedWithAWarning) {
  const WingCase c = wing_case(naca("9206", false), 0.2);
  ShellParams params;
  params.thickness = 0.4;
  params.min_thickness_fraction = 0.02;
  const NearField f = timed_shell(c, params, "cambered 9206, thick layer");
  expect_sound_shell(c, f, params);
  ASSERT_FALSE(f.warnings.empty());
  EXPECT_LT(f.thickness_min, params.thickness);
  bool on_lower = false;
  for (const auto& w : f.warnings) {
    EXPECT_NE(w.message.find("reduced"), std::string::npos) << w.message;
    on_lower |= w.message.find("'lower'") != std::string::npos;
  }
  EXPECT_TRUE(on_lower);

  // The documented gradation limit |δx − δy| <= gradation |x − y| over every body edge, with δ read
  // off the mesh (the length of each prism's vertical edge).
  std::map<NodeId, double> delta;
  for (std::size_t e = 0; e < f.mesh.elements().size(); ++e)
    for (int i = 0; i < 3; ++i) {
      const auto& v = f.mesh.elements()[e].vertices;
      delta[v[i]] = (f.mesh.node(v[i + 3]) - f.mesh.node(v[i])).norm();
    }
  int steeper = 0;
  double thinnest = params.thickness;
  for (std::size_t e = 0; e < f.mesh.elements().size(); ++e)
    for (int i = 0; i < 3; ++i) {
      const NodeId a = f.mesh.elements()[e].vertices[i], b = f.mesh.elements()[e].vertices[(i + 1) % 3];
      const double limit = params.gradation * (f.mesh.node(a) - f.mesh.node(b)).norm();
      steeper += std::abs(delta[a] - delta[b]) > limit * (1.0 + 1e-9) + 1e-12;
      thinnest = std::min(thinnest, delta[a]);
    }
  EXPECT_EQ(steeper, 0) << "body edges where the thickness changes faster than the gradation allows";
  EXPECT_NEAR(thinnest, f.thickness_min, 1e-9);
}

// The layer's checks run on all threads (each prism, each node on its own): the thinned shell of
// the concave section, rounds of reductions and all, is the same on one thread and on four.
TEST(OShell, SameShellOnOneThreadAndOnFour) {
  const WingCase c = wing_case(naca("9206", false), 0.2);
  ShellParams params;
  params.thickness = 0.4;
  params.min_thickness_fraction = 0.02;
  omp_set_num_threads(1);
  const NearField one = build_o_shell(*c.model, c.meshes, c.roles, params);
  omp_set_num_threads(4);
  const NearField four = build_o_shell(*c.model, c.meshes, c.roles, params);
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_LT(one.thickness_min, params.thickness);  // thinned: the checks found folds and crowding
  ASSERT_EQ(one.mesh.num_nodes(), four.mesh.num_nodes());
  for (NodeId v = 0; v < one.mesh.num_nodes(); ++v) ASSERT_EQ(one.mesh.node(v), four.mesh.node(v)) << "node " << v;
  ASSERT_EQ(one.mesh.elements().size(), four.mesh.elements().size());
  for (std::size_t e = 0; e < one.mesh.elements().size(); ++e)
    EXPECT_EQ(one.mesh.elements()[e].vertices, four.mesh.elements()[e].vertices) << "element " << e;
  EXPECT_EQ(one.warnings.size(), four.warnings.size());
}

TEST(OShell, ImpossibleThicknessThrowsWithThePlace) {
  const WingCase c = wing_case(naca("9206", false), 0.2);
  ShellParams params;
  params.thickness = 0.4;
  params.min_thickness_fraction = 0.9;
  try {
    build_o_shell(*c.model, c.meshes, c.roles, params);
    FAIL() << "expected NearFieldError";
  } catch (const NearFieldError& e) {
    const std::string what = e.what();
    std::cout << "error: " << what << "\n";
    EXPECT_NE(what.find("surface 1 ('lower')"), std::string::npos) << what;
    EXPECT_NE(what.find(" at ("), std::string::npos) << what;
    EXPECT_NE(what.find("min_thickness_fraction"), std::string::npos) << what;
  }
}

TEST(OShell, BadInputsNameTheProblem) {
  const WingCase c = wing_case(naca("0012", false), 0.8);
  auto message_of = [&](const BodyRoles& roles, const ShellParams& params) -> std::string {
    try {
      build_o_shell(*c.model, c.meshes, roles, params);
    } catch (const NearFieldError& e) {
      return e.what();
    }
    return "no error";
  };
  ShellParams bad_thickness;
  bad_thickness.thickness = -1.0;
  EXPECT_NE(message_of(c.roles, bad_thickness).find("nearfield.thickness = -1: expected > 0"), std::string::npos);
  BodyRoles no_wall = c.roles;
  no_wall.wall_surface = -1;
  EXPECT_NE(message_of(no_wall, {}).find("no wall surface"), std::string::npos);
  BodyRoles no_tip = c.roles;
  no_tip.body_surfaces.pop_back();  // the tip: the body is then open at the tip, away from the wall
  EXPECT_NE(message_of(no_tip, {}).find("away from the wall"), std::string::npos);
}

}  // namespace
}  // namespace semimesh::nearfield
