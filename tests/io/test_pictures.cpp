// SVG pictures: the cut draws one closed path per element the plane crosses, counted here from the
// elements' own vertices; the surface picture one outline per boundary face; the histogram counts.
#include "semimesh/io/pictures.hpp"

#include <gtest/gtest.h>

#include <regex>

namespace semimesh::io {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// n x n x n unit hexes filling [0, n]^3, the lower half in region "wing_layer", with the faces at
// z = 0 in group "wing" (straight elements: the plane crosses exactly those its vertices straddle).
mesh::Mesh block(int n) {
  mesh::Mesh m(1);
  const int lower = m.region_index("wing_layer"), upper = m.region_index("farfield");
  auto id = [n](int i, int j, int k) { return static_cast<mesh::NodeId>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.add_node({double(i), double(j), double(k)});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        m.add_element(ho::Shape::Hexahedron,
                      {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                       id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)},
                      2 * k < n ? lower : upper);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.add_boundary_face("wing", ho::Shape::Quadrilateral, {id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0)});
  return m;
}

TEST(Pictures, CutDrawsOneClosedPathPerCrossedElement) {
  const mesh::Mesh m = block(4);
  const CutPicture z = svg_cut(m, 2, 1.3, {}, "cut");
  EXPECT_EQ(z.elements_cut, 16u);  // one layer of 4 x 4 hexes straddles z = 1.3
  EXPECT_EQ(count(z.svg, "class=\"element\""), 16u);
  EXPECT_EQ(count(z.svg, " Z"), 16u);  // each a single closed loop
  EXPECT_NE(z.svg.find("wing_layer"), std::string::npos);  // legend of the region drawn
  EXPECT_EQ(z.svg.find(">farfield<"), std::string::npos);  // ... and only of those drawn
  // A window keeps the elements whose extent meets it: x in [0, 1.5] meets two columns of four.
  EXPECT_EQ(svg_cut(m, 0, 2.5, {0.0, 0.0, 1.5, 4.0}, "cropped").elements_cut, 8u);
  EXPECT_EQ(svg_cut(m, 1, 9.0, {}, "outside").elements_cut, 0u);
}

TEST(Pictures, SurfaceDrawsEveryFaceOfTheGroup) {
  const mesh::Mesh m = block(3);
  const std::string svg = svg_surface(m, "wing", 2, "from above");
  EXPECT_EQ(count(svg, "class=\"face\""), 9u);
  EXPECT_EQ(count(svg_surface(m, "wall", 2, "none"), "class=\"face\""), 0u);
}

TEST(Pictures, HistogramCountsTheInvalidOnes) {
  const std::string svg = svg_histogram({{"prism", {0.5, 0.51, -0.2, 0.9}}, {"tetrahedron", {1.0, 0.0}}}, "quality");
  EXPECT_NE(svg.find("(2 invalid)"), std::string::npos) << svg;  // -0.2 and an unproven 0
  EXPECT_NE(svg.find("<title>prism 2</title>"), std::string::npos);  // 0.5 and 0.51 share a bin
  EXPECT_EQ(count(svg, "class=\"bar\""), 5u);
}

}  // namespace
}  // namespace semimesh::io
