// Canonical node order against independent sources:
//  - Gmsh itself: gmsh_reference_nodes.py (run with Debian's python3, which has the gmsh module)
//    prints Gmsh 4.8's reference nodes, in MSH order, for every shape and order Gmsh knows;
//  - prisms of order 3..6, which Gmsh 4.8 cannot describe: PyFR's published Gmsh node maps
//    (PyFR/PyFR, pyfr/readers/nodemaps.py, GmshNodeMaps.to_pyfr[('pri', n)]), which give, for each
//    Gmsh node, its index in PyFR's lexicographic prism layout (z-layer, then triangle row, then x).
#include "semimesh/ho/element_type.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::ho {
namespace {

// The script's output: family -> order -> rows of 3 coordinates. A small parser for exactly the
// JSON the script writes (objects of string keys, arrays, numbers).
using GmshNodes = std::map<std::string, std::map<int, std::vector<std::vector<double>>>>;

class JsonReader {
 public:
  explicit JsonReader(const std::string& text) : text_(text) {}

  GmshNodes read() {
    GmshNodes out;
    expect('{');
    while (peek() != '}') {
      const std::string family = string();
      expect(':');
      expect('{');
      while (peek() != '}') {
        const int order = std::stoi(string());
        expect(':');
        out[family][order] = rows();
        if (peek() == ',') ++pos_;
      }
      expect('}');
      if (peek() == ',') ++pos_;
    }
    expect('}');
    return out;
  }

 private:
  char peek() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (pos_ >= text_.size()) throw std::runtime_error("gmsh JSON: unexpected end");
    return text_[pos_];
  }
  void expect(char c) {
    if (peek() != c) throw std::runtime_error(std::string("gmsh JSON: expected '") + c + "' at " + std::to_string(pos_));
    ++pos_;
  }
  std::string string() {
    expect('"');
    const std::size_t end = text_.find('"', pos_);
    std::string s = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }
  std::vector<double> numbers() {
    std::vector<double> out;
    expect('[');
    while (peek() != ']') {
      std::size_t used = 0;
      out.push_back(std::stod(text_.substr(pos_, 40), &used));
      pos_ += used;
      if (peek() == ',') ++pos_;
    }
    expect(']');
    return out;
  }
  std::vector<std::vector<double>> rows() {
    std::vector<std::vector<double>> out;
    expect('[');
    while (peek() != ']') {
      out.push_back(numbers());
      if (peek() == ',') ++pos_;
    }
    expect(']');
    return out;
  }

  const std::string& text_;
  std::size_t pos_ = 0;
};

// Runs the script once; an empty result means Gmsh's python module is not available here.
const GmshNodes& gmsh_nodes() {
  static const GmshNodes nodes = [] {
    const std::string command =
        std::string(SEMIMESH_GMSH_PYTHON) + " " + SEMIMESH_GMSH_NODES_SCRIPT + " 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string text;
    if (pipe) {
      char buffer[65536];
      std::size_t n = 0;
      while ((n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0) text.append(buffer, n);
    }
    return text.empty() ? GmshNodes{} : JsonReader(text).read();
  }();
  return nodes;
}

struct Family {
  const char* gmsh_name;
  Shape shape;
};
const Family kFamilies[] = {{"Line", Shape::Segment},          {"Triangle", Shape::Triangle},
                            {"Quadrangle", Shape::Quadrilateral}, {"Tetrahedron", Shape::Tetrahedron},
                            {"Pyramid", Shape::Pyramid},        {"Prism", Shape::Prism},
                            {"Hexahedron", Shape::Hexahedron}};

TEST(GmshNodeOrder, EquispacedNodesMatchGmshExactly) {
  const GmshNodes& gmsh = gmsh_nodes();
  if (gmsh.empty()) GTEST_SKIP() << "no gmsh python module at " << SEMIMESH_GMSH_PYTHON;
  int compared = 0;
  for (const Family& family : kFamilies) {
    const auto found = gmsh.find(family.gmsh_name);
    ASSERT_NE(found, gmsh.end()) << family.gmsh_name;
    for (const auto& [order, rows] : found->second) {
      if (order > kMaxOrder) continue;
      const Eigen::MatrixX3d nodes = reference_nodes(family.shape, order);
      ASSERT_EQ(static_cast<std::size_t>(nodes.rows()), rows.size()) << family.gmsh_name << " order " << order;
      for (std::size_t i = 0; i < rows.size(); ++i)
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(nodes(i, k), rows[i][k], 1e-12) << family.gmsh_name << " order " << order << " node " << i;
      ++compared;
    }
  }
  // Gmsh 4.8: segments, triangles, quads, tets to order 10, pyramids and hexes to 9, prisms to 2.
  EXPECT_GE(compared, 4 * 10 + 2 * 9 + 2);
}

// PyFR GmshNodeMaps.to_pyfr[('pri', n)]: entry i is the PyFR index of Gmsh node i.
const std::map<int, std::vector<int>>& pyfr_prism_maps() {
  static const std::map<int, std::vector<int>> maps{
      {3, {0,  3,  9,  30, 33, 39, 1,  2,  4,  7,  10, 20, 6,  8,  13, 23, 19, 29, 31, 32,
           34, 37, 36, 38, 5,  35, 11, 12, 22, 21, 14, 24, 27, 17, 16, 18, 28, 26, 15, 25}},
      {4, {0,  4,  14, 60, 64, 74, 1,  2,  3,  5,  9,  12, 15, 30, 45, 8,  11, 13, 19, 34, 49, 29, 44, 59, 61,
           62, 63, 65, 69, 72, 68, 71, 73, 6,  10, 7,  66, 67, 70, 16, 18, 48, 46, 17, 33, 47, 31, 32, 20, 50,
           57, 27, 35, 54, 42, 24, 39, 23, 28, 58, 53, 26, 43, 56, 38, 41, 21, 51, 36, 22, 52, 37, 25, 55, 40}},
      {5, {0,   5,   20,  105, 110, 125, 1,   2,   3,   4,   6,   11,  15,  18,  21,  42,  63,  84,  10,  14,  17,
           19,  26,  47,  68,  89,  41,  62,  83,  104, 106, 107, 108, 109, 111, 116, 120, 123, 115, 119, 122, 124,
           7,   16,  9,   12,  13,  8,   112, 114, 121, 113, 118, 117, 22,  25,  88,  85,  23,  24,  46,  67,  87,
           86,  64,  43,  44,  45,  66,  65,  27,  90,  102, 39,  48,  69,  95,  99,  81,  60,  36,  32,  53,  74,
           78,  57,  31,  40,  103, 94,  35,  38,  61,  82,  101, 98,  73,  52,  56,  59,  80,  77,  28,  91,  49,
           70,  30,  93,  51,  72,  37,  100, 58,  79,  29,  92,  50,  71,  34,  97,  55,  76,  33,  96,  54,  75}},
      {6, {0,   6,   27,  168, 174, 195, 1,   2,   3,   4,   5,   7,   13,  18,  22,  25,  28,  56,  84,  112,
           140, 12,  17,  21,  24,  26,  34,  62,  90,  118, 146, 55,  83,  111, 139, 167, 169, 170, 171, 172,
           173, 175, 181, 186, 190, 193, 180, 185, 189, 192, 194, 8,   23,  11,  14,  19,  20,  16,  10,  9,
           15,  176, 179, 191, 177, 178, 184, 188, 187, 182, 183, 29,  33,  145, 141, 30,  31,  32,  61,  89,
           117, 144, 143, 142, 113, 85,  57,  58,  60,  116, 114, 59,  88,  115, 86,  87,  35,  147, 165, 53,
           63,  91,  119, 153, 158, 162, 137, 109, 81,  50,  46,  41,  69,  125, 134, 78,  97,  130, 106, 74,
           102, 40,  54,  166, 152, 45,  49,  52,  82,  110, 138, 164, 161, 157, 124, 96,  68,  73,  80,  136,
           129, 77,  108, 133, 101, 105, 36,  148, 64,  92,  120, 39,  151, 67,  95,  123, 51,  163, 79,  107,
           135, 37,  149, 65,  93,  121, 38,  150, 66,  94,  122, 44,  156, 72,  100, 128, 48,  160, 76,  104,
           132, 47,  159, 75,  103, 131, 42,  154, 70,  98,  126, 43,  155, 71,  99,  127}}};
  return maps;
}

// PyFR's prism layout: index = layer * (triangle size) + row offset + column, layers along z in [-1, 1],
// rows along y, columns along x, all equispaced.
Eigen::Vector3d pyfr_prism_point(int order, int index) {
  const int triangle_size = (order + 1) * (order + 2) / 2;
  const int layer = index / triangle_size;
  int rest = index % triangle_size, row = 0;
  while (rest >= order + 1 - row) rest -= order + 1 - row++;
  return {double(rest) / order, double(row) / order, -1.0 + 2.0 * layer / order};
}

TEST(GmshNodeOrder, PrismsOfOrder3To6MatchPyFRsGmshNodeMaps) {
  for (const auto& [order, map] : pyfr_prism_maps()) {
    const Eigen::MatrixX3d nodes = reference_nodes(Shape::Prism, order);
    ASSERT_EQ(static_cast<std::size_t>(nodes.rows()), map.size()) << "prism order " << order;
    for (std::size_t i = 0; i < map.size(); ++i)
      ASSERT_LT((nodes.row(i).transpose() - pyfr_prism_point(order, map[i])).norm(), 1e-12)
          << "prism order " << order << " gmsh node " << i;
  }
}

}  // namespace
}  // namespace semimesh::ho
