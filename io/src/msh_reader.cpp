#include "semimesh/io/gmsh_types.hpp"
#include "semimesh/io/msh.hpp"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace semimesh::io {
namespace {

/// Reads a text file line by line and splits lines into numbers, keeping the line number for
/// error messages.
class Lines {
 public:
  explicit Lines(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw std::runtime_error(path + ": cannot open the file for reading");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(path_ + ":" + std::to_string(line_) + ": " + what);
  }

  bool next(std::string& text) {
    if (!std::getline(in_, text)) return false;
    ++line_;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return true;
  }

  std::string require(const char* expected) {
    std::string text;
    if (!next(text)) fail(std::string("unexpected end of file, expected ") + expected);
    return text;
  }

  /// Whitespace-separated numbers of the next line (at least `min_count`).
  const std::vector<double>& numbers(std::size_t min_count, const char* expected) {
    const std::string text = require(expected);
    values_.clear();
    const char* p = text.c_str();
    char* end = nullptr;
    for (;;) {
      const double v = std::strtod(p, &end);
      if (end == p) break;
      values_.push_back(v);
      p = end;
    }
    while (*p == ' ' || *p == '\t') ++p;
    if (*p != '\0' || values_.size() < min_count) fail(std::string("expected ") + expected + ", got '" + text + "'");
    return values_;
  }

  int line() const { return line_; }

  /// Raw little-endian values of a binary file's data (count of them), failing at the end of file.
  template <typename T>
  void raw(T* values, std::size_t count, const char* expected) {
    if (!in_.read(reinterpret_cast<char*>(values), static_cast<std::streamsize>(count * sizeof(T))))
      fail(std::string("unexpected end of file in binary data, expected ") + expected);
  }
  template <typename T>
  T raw(const char* expected) {
    T v{};
    raw(&v, 1, expected);
    return v;
  }

 private:
  std::string path_;
  std::ifstream in_;
  int line_ = 0;
  std::vector<double> values_;
};

struct RawElement {
  ho::Shape shape;
  int order;
  int physical;  // 2D: physical tag, -1 if none
  int line;
  std::vector<long> nodes;
};

struct Parsed {
  double version = 0;
  bool binary = false;  // MSH 4.1 file-type 1: $Entities, $Nodes, $Elements hold raw data
  std::map<std::pair<int, int>, std::string> names;  // (dim, physical tag) -> name
  std::map<int, int> surface_physical;              // surface entity tag -> first physical tag
  std::vector<long> node_tags;
  std::vector<Eigen::Vector3d> node_xyz;
  std::vector<RawElement> elements;
};

void skip_to_end(Lines& in, const std::string& section) {
  std::string text;
  while (in.next(text))
    if (text == "$End" + section) return;
  in.fail("missing $End" + section);
}

void expect_end(Lines& in, const std::string& section) {
  const std::string text = in.require(("$End" + section).c_str());
  if (text != "$End" + section) in.fail("expected $End" + section + ", got '" + text + "'");
}

void add_element(Lines& in, Parsed& p, int type, int physical, const double* nodes, std::size_t count) {
  ho::Shape shape;
  int order = 0;
  if (!gmsh_shape_and_order(type, shape, order)) return;  // points, lines, serendipity: not mesh elements
  if (shape != ho::Shape::Triangle && shape != ho::Shape::Quadrilateral && ho::dimension(shape) != 3) return;
  const auto expected = static_cast<std::size_t>(ho::num_nodes(shape, order));
  if (count != expected)
    in.fail("element of type " + std::to_string(type) + " needs " + std::to_string(expected) + " nodes, got " +
            std::to_string(count));
  RawElement raw{shape, order, physical, in.line(), {}};
  for (std::size_t i = 0; i < count; ++i) raw.nodes.push_back(static_cast<long>(nodes[i]));
  p.elements.push_back(std::move(raw));
}

void read_entities(Lines& in, Parsed& p) {
  const auto& counts = in.numbers(4, "4 entity counts");
  const long n[4] = {static_cast<long>(counts[0]), static_cast<long>(counts[1]), static_cast<long>(counts[2]),
                     static_cast<long>(counts[3])};
  for (int dim = 0; dim < 4; ++dim)
    for (long i = 0; i < n[dim]; ++i) {
      const std::size_t first_phys = dim == 0 ? 4 : 7;  // tag, point or box, numPhysicalTags
      const auto& v = in.numbers(first_phys + 1, "an entity line");
      const auto nphys = static_cast<std::size_t>(v[first_phys]);
      if (dim == 2 && nphys > 0) {
        if (v.size() < first_phys + 2) in.fail("entity line lists fewer physical tags than it declares");
        p.surface_physical[static_cast<int>(v[0])] = static_cast<int>(v[first_phys + 1]);
      }
    }
  expect_end(in, "Entities");
}

void read_nodes(Lines& in, Parsed& p) {
  if (p.version >= 4) {
    const auto& head = in.numbers(4, "numEntityBlocks numNodes minNodeTag maxNodeTag");
    const auto blocks = static_cast<long>(head[0]);
    for (long b = 0; b < blocks; ++b) {
      const auto& bh = in.numbers(4, "entityDim entityTag parametric numNodesInBlock");
      const auto count = static_cast<long>(bh[3]);
      for (long i = 0; i < count; ++i) p.node_tags.push_back(static_cast<long>(in.numbers(1, "a node tag")[0]));
      for (long i = 0; i < count; ++i) {
        const auto& x = in.numbers(3, "node coordinates x y z");
        p.node_xyz.emplace_back(x[0], x[1], x[2]);
      }
    }
  } else {
    const auto count = static_cast<long>(in.numbers(1, "the number of nodes")[0]);
    for (long i = 0; i < count; ++i) {
      const auto& v = in.numbers(4, "node-number x y z");
      p.node_tags.push_back(static_cast<long>(v[0]));
      p.node_xyz.emplace_back(v[1], v[2], v[3]);
    }
  }
  expect_end(in, "Nodes");
}

void read_elements(Lines& in, Parsed& p) {
  if (p.version >= 4) {
    const auto& head = in.numbers(4, "numEntityBlocks numElements minElementTag maxElementTag");
    const auto blocks = static_cast<long>(head[0]);
    for (long b = 0; b < blocks; ++b) {
      const auto& bh = in.numbers(4, "entityDim entityTag elementType numElementsInBlock");
      const int dim = static_cast<int>(bh[0]), tag = static_cast<int>(bh[1]), type = static_cast<int>(bh[2]);
      const auto count = static_cast<long>(bh[3]);
      int physical = -1;
      if (dim == 2 && p.surface_physical.count(tag)) physical = p.surface_physical[tag];
      for (long i = 0; i < count; ++i) {
        const auto& v = in.numbers(2, "elementTag nodeTags...");
        add_element(in, p, type, physical, v.data() + 1, v.size() - 1);
      }
    }
  } else {
    const auto count = static_cast<long>(in.numbers(1, "the number of elements")[0]);
    for (long i = 0; i < count; ++i) {
      const auto& v = in.numbers(3, "elm-number elm-type number-of-tags tags... nodes...");
      const auto ntags = static_cast<std::size_t>(v[2]);
      if (v.size() < 3 + ntags) in.fail("element line has fewer tags than it declares");
      const int physical = ntags > 0 ? static_cast<int>(v[3]) : -1;
      add_element(in, p, static_cast<int>(v[1]), physical, v.data() + 3 + ntags, v.size() - 3 - ntags);
    }
  }
  expect_end(in, "Elements");
}

// Binary MSH 4.1 (file-type 1, data-size 8, little endian): ints for entity dimensions, tags and
// types, size_t for counts and node/element tags, doubles for coordinates; a newline ends the data.
void end_binary(Lines& in, const std::string& section) {
  const std::string rest = in.require(("$End" + section).c_str());
  if (!rest.empty()) in.fail("expected the end of the binary " + section + " data, got more bytes");
  expect_end(in, section);
}

void read_entities_binary(Lines& in, Parsed& p) {
  std::size_t n[4];
  in.raw(n, 4, "4 entity counts");
  for (int dim = 0; dim < 4; ++dim)
    for (std::size_t i = 0; i < n[dim]; ++i) {
      const int tag = in.raw<int>("an entity tag");
      double box[6];
      in.raw(box, dim == 0 ? 3 : 6, "an entity's point or box");
      std::vector<int> physical(in.raw<std::size_t>("numPhysicalTags"));
      in.raw(physical.data(), physical.size(), "physical tags");
      if (dim == 2 && !physical.empty()) p.surface_physical[tag] = physical.front();
      if (dim == 0) continue;
      std::vector<int> bounding(in.raw<std::size_t>("numBoundingEntities"));
      in.raw(bounding.data(), bounding.size(), "bounding entity tags");
    }
  end_binary(in, "Entities");
}

void read_nodes_binary(Lines& in, Parsed& p) {
  std::size_t head[4];
  in.raw(head, 4, "numEntityBlocks numNodes minNodeTag maxNodeTag");
  for (std::size_t b = 0; b < head[0]; ++b) {
    int block[3];
    in.raw(block, 3, "entityDim entityTag parametric");
    if (block[2] != 0) in.fail("parametric node coordinates are not supported");
    const std::size_t count = in.raw<std::size_t>("numNodesInBlock");
    std::vector<std::size_t> tags(count);
    in.raw(tags.data(), count, "node tags");
    std::vector<double> xyz(3 * count);
    in.raw(xyz.data(), xyz.size(), "node coordinates");
    for (std::size_t i = 0; i < count; ++i) {
      p.node_tags.push_back(static_cast<long>(tags[i]));
      p.node_xyz.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    }
  }
  end_binary(in, "Nodes");
}

void read_elements_binary(Lines& in, Parsed& p) {
  std::size_t head[4];
  in.raw(head, 4, "numEntityBlocks numElements minElementTag maxElementTag");
  std::vector<std::size_t> data;
  std::vector<double> nodes;
  for (std::size_t b = 0; b < head[0]; ++b) {
    int block[3];
    in.raw(block, 3, "entityDim entityTag elementType");
    const std::size_t count = in.raw<std::size_t>("numElementsInBlock");
    const int dim = block[0], tag = block[1], type = block[2];
    // The record length comes from the type: only the types read_msh keeps can be skipped over.
    ho::Shape shape;
    int order = 0;
    if (!gmsh_shape_and_order(type, shape, order))
      in.fail("element type " + std::to_string(type) + " in a binary file: only volume elements, triangles and "
              "quadrangles can be read");
    const auto per = static_cast<std::size_t>(ho::num_nodes(shape, order));
    data.resize(count * (per + 1));
    in.raw(data.data(), data.size(), "elementTag nodeTags...");
    int physical = -1;
    if (dim == 2 && p.surface_physical.count(tag)) physical = p.surface_physical[tag];
    nodes.resize(per);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t k = 0; k < per; ++k) nodes[k] = static_cast<double>(data[i * (per + 1) + 1 + k]);
      add_element(in, p, type, physical, nodes.data(), per);
    }
  }
  end_binary(in, "Elements");
}

void read_physical_names(Lines& in, Parsed& p) {
  const auto count = static_cast<long>(in.numbers(1, "the number of physical names")[0]);
  for (long i = 0; i < count; ++i) {
    const std::string text = in.require("dimension tag \"name\"");
    const auto q0 = text.find('"'), q1 = text.rfind('"');
    if (q0 == std::string::npos || q1 == q0) in.fail("expected dimension tag \"name\", got '" + text + "'");
    int dim = 0, tag = 0;
    if (std::sscanf(text.c_str(), "%d %d", &dim, &tag) != 2) in.fail("expected dimension tag \"name\", got '" + text + "'");
    p.names[{dim, tag}] = text.substr(q0 + 1, q1 - q0 - 1);
  }
  expect_end(in, "PhysicalNames");
}

}  // namespace

mesh::Mesh read_msh(const std::string& path) {
  Lines in(path);
  Parsed p;
  std::string text;
  while (in.next(text)) {
    if (text.empty()) continue;
    if (text == "$MeshFormat") {
      const auto& v = in.numbers(3, "version file-type data-size");
      p.version = v[0];
      if (p.version != 2.2 && p.version != 4.1)
        in.fail("MSH version " + std::to_string(v[0]) + " is not supported (2.2 or 4.1)");
      p.binary = v[1] != 0;
      if (p.binary) {
        if (p.version != 4.1) in.fail("binary MSH is read in version 4.1 only");
        if (v[2] != 8) in.fail("binary MSH with data-size " + std::to_string(static_cast<int>(v[2])) + ": 8 expected");
        if (in.raw<int>("the endianness check 1") != 1) in.fail("big-endian binary MSH is not supported");
        in.require("the end of the endianness line");
      }
      expect_end(in, "MeshFormat");
    } else if (p.version == 0) {
      in.fail("expected $MeshFormat first, got '" + text + "'");
    } else if (text == "$PhysicalNames") {
      read_physical_names(in, p);
    } else if (text == "$Entities") {
      p.binary ? read_entities_binary(in, p) : read_entities(in, p);
    } else if (text == "$Nodes") {
      p.binary ? read_nodes_binary(in, p) : read_nodes(in, p);
    } else if (text == "$Elements") {
      p.binary ? read_elements_binary(in, p) : read_elements(in, p);
    } else if (text.size() > 1 && text[0] == '$') {
      skip_to_end(in, text.substr(1));
    } else {
      in.fail("expected a section ($Nodes, $Elements...), got '" + text + "'");
    }
  }
  if (p.version == 0) in.fail("no $MeshFormat section: not a MSH file");

  // One order for the whole mesh, taken from the first volume element (or first face).
  int order = 0;
  for (const auto& e : p.elements)
    if (ho::dimension(e.shape) == 3) {
      order = e.order;
      break;
    }
  if (order == 0 && !p.elements.empty()) order = p.elements.front().order;
  mesh::Mesh result(order == 0 ? 1 : order, ho::NodeSet::Equispaced);
  std::unordered_map<long, mesh::NodeId> id_of;
  id_of.reserve(p.node_tags.size());
  for (std::size_t i = 0; i < p.node_tags.size(); ++i) id_of[p.node_tags[i]] = result.add_node(p.node_xyz[i]);

  auto located = [&](const RawElement& e, const std::string& what) {
    return std::runtime_error(path + ":" + std::to_string(e.line) + ": " + what);
  };
  std::vector<mesh::NodeId> ids;
  for (int pass = 0; pass < 2; ++pass)  // volume elements first, so faces take their orientation
    for (const auto& e : p.elements) {
      if ((ho::dimension(e.shape) == 3) != (pass == 0)) continue;
      if (e.order != result.order())
        throw located(e, "element of order " + std::to_string(e.order) + " in a mesh of order " +
                             std::to_string(result.order()) + " (mixed orders are not supported)");
      ids.clear();
      for (long tag : e.nodes) {
        const auto it = id_of.find(tag);
        if (it == id_of.end()) throw located(e, "element refers to node " + std::to_string(tag) + " not in $Nodes");
        ids.push_back(it->second);
      }
      try {
        if (pass == 0) {
          result.add_element(e.shape, ids);
        } else {
          std::string group = "unassigned";
          if (e.physical >= 0) {
            const auto it = p.names.find({2, e.physical});
            group = it != p.names.end() ? it->second : "surface_" + std::to_string(e.physical);
          }
          result.add_boundary_face(group, e.shape, ids);
        }
      } catch (const std::invalid_argument& err) {
        throw located(e, err.what());
      }
    }
  return result;
}

}  // namespace semimesh::io
