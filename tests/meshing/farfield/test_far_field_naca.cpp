// The far field around the O-type prism shell of a NACA0012 wing on its wall: the whole mesh
// (prisms + tets) must be conforming and closed.
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/o_shell.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace semimesh::farfield {
namespace {

using mesh::NodeId;
using FaceKey = std::array<NodeId, 4>;  // sorted vertex ids, kNoNode-padded for triangles

FaceKey key_of(const std::vector<NodeId>& v) {
  FaceKey k{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode, mesh::kNoNode};
  std::copy(v.begin(), v.end(), k.begin());
  std::sort(k.begin(), k.end());
  return k;
}

TEST(FarFieldNaca0012, ConformingClosedMeshAroundTheOShell) {
  mock_cad::NacaWingParams wing;
  wing.span = 1.0;
  wing.box = {-2, -2, 0, 3, 2, 2};
  const auto model = mock_cad::make_naca_wing(wing);
  surface::SizeParams size;
  size.max_size = 0.3;
  size.min_size = 0.01;
  size.curvature_segments = 2.0;
  size.gradation = 1.3;
  size.le_size = 0.04;
  size.te_size = 0.04;
  const surface::SurfaceMeshes meshes = surface::mesh_model_surfaces(*model, surface::SizeField(*model, size));
  nearfield::BodyRoles roles;
  for (const char* name : {"upper", "lower", "te_base", "tip"}) roles.body_surfaces.push_back(*model->find_surface(name));
  roles.wall_surface = *model->find_surface("wall");
  nearfield::ShellParams shell;
  shell.thickness = 0.03;
  nearfield::NearField nf = nearfield::build_o_shell(*model, meshes, roles, shell);
  const std::size_t prisms = nf.mesh.elements().size();

  std::vector<int> box;
  for (const char* name : {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}) box.push_back(*model->find_surface(name));
  FarFieldParams params;
  params.box_size = 0.8;
  params.wall_size = 0.5;
  const FarField far = build_far_field(*model, nf, params, box, roles.wall_surface);
  const FarFieldStats& stats = far.stats;
  const mesh::Mesh& m = far.mesh;
  EXPECT_EQ(stats.pyramids, 0);  // the O-shell's skin is all triangles
  EXPECT_EQ(m.elements().size(), prisms + stats.tets);
  // TetGen meshes the interior points it is given and refines little after them (2 % of its input,
  // which is fewer points than the mesh's).
  EXPECT_GT(stats.interior_points, stats.tets / 10);
  EXPECT_LE(stats.added_points, std::ceil(0.02 * static_cast<double>(m.num_nodes())));
  // Every node is some element's: an interior point TetGen carved away is not kept.
  std::vector<char> used(m.num_nodes(), 0);
  for (const auto& el : m.elements())
    for (NodeId v : el.vertices) used[v] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  // The shell's prisms are the wing layer, the far field's tets their own region.
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    ASSERT_EQ(m.region_names()[m.elements()[e].region], e < prisms ? "wing_layer" : "farfield") << "element " << e;

  std::map<FaceKey, int> element_faces;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const auto& el = m.elements()[e];
    if (el.shape == ho::Shape::Tetrahedron) {
      const auto x = m.element_coordinates(e);
      const double volume = (x.row(1) - x.row(0)).cross(x.row(2) - x.row(0)).dot(x.row(3) - x.row(0)) / 6.0;
      EXPECT_GT(volume, 0.0) << "tet " << e;
    }
    for (const auto& f : ho::faces(el.shape)) {
      std::vector<NodeId> v;
      for (int k : f) v.push_back(el.vertices[k]);
      ++element_faces[key_of(v)];
    }
  }
  for (const auto& s : nf.skin) EXPECT_EQ(element_faces[key_of({s.nodes[0], s.nodes[1], s.nodes[2]})], 2);
  std::map<FaceKey, int> boundary;
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    const auto& bf = m.boundary_faces()[b];
    const int n = bf.shape == ho::Shape::Triangle ? 3 : 4;
    ++boundary[key_of(std::vector<NodeId>(bf.vertices.begin(), bf.vertices.begin() + n))];
  }
  int open = 0, overused = 0, boundary_mismatch = 0;
  for (const auto& [face, count] : element_faces) {
    if (count > 2) ++overused;
    if (count == 1 && !boundary.count(face)) ++open;
    if (count == 2 && boundary.count(face)) ++boundary_mismatch;
  }
  EXPECT_EQ(open, 0) << "element faces on no boundary group";
  EXPECT_EQ(overused, 0);
  EXPECT_EQ(boundary_mismatch, 0) << "boundary faces between two elements";
  for (const auto& [face, count] : boundary) EXPECT_EQ(element_faces[face], 1);
  std::cout << "NACA0012 far field: " << prisms << " prisms, " << stats.tets << " tets, " << stats.wall_triangles
            << " wall and " << stats.box_triangles << " box triangles, TetGen " << stats.seconds_tetgen << " s\n";
}

}  // namespace
}  // namespace semimesh::farfield
