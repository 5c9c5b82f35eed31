// A half model's symmetry plane: the far field's faces on one side of the box leave group
// "farfield" for "symmetry" (farfield.symmetry), found by position.
#include "semimesh/farfield/detail/symmetry_faces.hpp"

#include "semimesh/farfield/far_field.hpp"

#include <gtest/gtest.h>

#include <set>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

// The unit cube's six faces as "farfield" quads (the wall layer's sides on a box are quads), the
// zmin face split into two triangles, and a "wall" quad on the zmin plane inside it; one more
// triangle leaning off the zmin plane with two vertices on it.
mesh::Mesh cube() {
  mesh::Mesh m;
  std::vector<mesh::NodeId> v;
  for (int k = 0; k < 8; ++k) v.push_back(m.add_node(Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1)));
  const auto apex = m.add_node(Vector3d(0.5, 0.5, 0.5));
  const auto inner = {m.add_node(Vector3d(0.2, 0.2, 0)), m.add_node(Vector3d(0.4, 0.2, 0)),
                      m.add_node(Vector3d(0.4, 0.4, 0)), m.add_node(Vector3d(0.2, 0.4, 0))};
  m.add_boundary_face("farfield", ho::Shape::Triangle, {v[0], v[2], v[1]});
  m.add_boundary_face("farfield", ho::Shape::Triangle, {v[1], v[2], v[3]});
  m.add_boundary_face("farfield", ho::Shape::Quadrilateral, {v[4], v[5], v[7], v[6]});  // zmax
  m.add_boundary_face("farfield", ho::Shape::Quadrilateral, {v[0], v[1], v[5], v[4]});  // ymin
  m.add_boundary_face("farfield", ho::Shape::Quadrilateral, {v[2], v[6], v[7], v[3]});  // ymax
  m.add_boundary_face("farfield", ho::Shape::Quadrilateral, {v[0], v[4], v[6], v[2]});  // xmin
  m.add_boundary_face("farfield", ho::Shape::Quadrilateral, {v[1], v[3], v[7], v[5]});  // xmax
  m.add_boundary_face("farfield", ho::Shape::Triangle, {v[0], v[1], apex});             // off the plane
  m.add_boundary_face("wall", ho::Shape::Quadrilateral, std::vector<mesh::NodeId>(inner));
  return m;
}

std::multiset<std::string> groups_of(const mesh::Mesh& m) {
  std::multiset<std::string> names;
  for (const mesh::BoundaryFace& f : m.boundary_faces()) names.insert(m.group_names()[f.group]);
  return names;
}

TEST(SymmetryFaces, MovesTheFarFieldFacesOnTheSideAndNoOther) {
  mesh::Mesh m = cube();
  EXPECT_EQ(move_symmetry_faces(m, "zmin", 1e-12), 2);
  for (std::size_t i = 0; i < m.boundary_faces().size(); ++i) {
    const std::string& group = m.group_names()[m.boundary_faces()[i].group];
    EXPECT_EQ(group, i < 2 ? "symmetry" : i == 8 ? "wall" : "farfield") << "face " << i;
  }
}

TEST(SymmetryFaces, FindsTheMaximumSideOfEachAxis) {
  for (const char* side : {"xmax", "ymin", "zmax"}) {
    mesh::Mesh m = cube();
    EXPECT_EQ(move_symmetry_faces(m, side, 1e-12), 1) << side;
    EXPECT_EQ(groups_of(m).count("symmetry"), 1u) << side;
  }
}

TEST(SymmetryFaces, ToleratesRoundOffButNotAStep) {
  mesh::Mesh m = cube();
  m.place_node(5, m.node(5) + Vector3d(1e-13, 0, 0));  // xmax face's corner off by round-off
  EXPECT_EQ(move_symmetry_faces(m, "xmax", 1e-12), 1);
  mesh::Mesh stepped = cube();
  stepped.place_node(5, stepped.node(5) + Vector3d(1e-6, 0, 0));  // now the corner alone is extreme
  EXPECT_THROW(move_symmetry_faces(stepped, "xmax", 1e-12), FarFieldError);
}

TEST(SymmetryFaces, RefusesAnUnknownSideOrASideWithNoFlatFace) {
  mesh::Mesh m = cube();
  try {
    move_symmetry_faces(m, "bottom", 1e-12);
    FAIL() << "an unknown side was accepted";
  } catch (const FarFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("farfield.symmetry = \"bottom\""), std::string::npos) << e.what();
  }
  mesh::Mesh no_far_field;
  no_far_field.add_boundary_face("wall", ho::Shape::Triangle,
                                 {no_far_field.add_node(Vector3d(0, 0, 0)), no_far_field.add_node(Vector3d(1, 0, 0)),
                                  no_far_field.add_node(Vector3d(0, 1, 0))});
  try {
    move_symmetry_faces(no_far_field, "zmin", 1e-12);
    FAIL() << "a mesh with no far-field face lying on the side was accepted";
  } catch (const FarFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("no far-field face lies on the plane"), std::string::npos) << e.what();
  }
  EXPECT_EQ(groups_of(no_far_field), std::multiset<std::string>{"wall"});
}

}  // namespace
}  // namespace semimesh::farfield
