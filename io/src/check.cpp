#include "semimesh/io/check.hpp"

#include "semimesh/ho/validity.hpp"
#include "semimesh/io/msh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <map>

namespace semimesh::io {
namespace {

struct Invalid {
  std::size_t index;
  ho::Shape shape;
  Eigen::Vector3d centroid;
};

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

int run_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string path;
  bool json = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i == 0 && args[i] == "check") continue;
    if (args[i] == "--json")
      json = true;
    else if (!args[i].empty() && args[i][0] == '-') {
      err << "semimesh check: unknown option '" << args[i] << "' (usage: semimesh check MESH.msh [--json])\n";
      return 1;
    } else if (path.empty())
      path = args[i];
    else {
      err << "semimesh check: one mesh file expected, got '" << path << "' and '" << args[i] << "'\n";
      return 1;
    }
  }
  if (path.empty()) {
    err << "semimesh check: no mesh file given (usage: semimesh check MESH.msh [--json])\n";
    return 1;
  }
  mesh::Mesh m;
  try {
    m = read_msh(path);
  } catch (const std::exception& e) {
    err << "semimesh check: " << e.what() << "\n";
    return 1;
  }

  std::map<std::string, std::map<int, std::size_t>> counts;
  std::vector<Invalid> invalid;
  std::vector<double> scaled;
  scaled.reserve(m.elements().size());
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const ho::Shape shape = m.elements()[e].shape;
    ++counts[ho::to_string(shape)][m.order()];
    const Eigen::MatrixX3d x = m.element_coordinates(e);
    const ho::JacobianBounds bounds = ho::certify_jacobian(shape, m.order(), m.node_set(), x);
    scaled.push_back(ho::scaled_jacobian(bounds));
    if (!bounds.valid) {
      const int nv = ho::num_vertices(shape);
      invalid.push_back({e, shape, x.topRows(nv).colwise().mean().transpose()});
    }
  }
  for (const auto& b : m.boundary_faces()) ++counts[ho::to_string(b.shape)][m.order()];
  double min_sj = 0, median_sj = 0;
  if (!scaled.empty()) {
    std::sort(scaled.begin(), scaled.end());
    min_sj = scaled.front();
    const std::size_t n = scaled.size();
    median_sj = n % 2 ? scaled[n / 2] : 0.5 * (scaled[n / 2 - 1] + scaled[n / 2]);
  }

  if (json) {
    std::string s = "{\"file\": " + json_string(path) + ", \"elements\": {";
    bool first = true;
    for (const auto& [type, by_order] : counts) {
      s += fmt::format("{}{}: {{", first ? "" : ", ", json_string(type));
      bool first_order = true;
      for (const auto& [order, n] : by_order) {
        s += fmt::format("{}\"{}\": {}", first_order ? "" : ", ", order, n);
        first_order = false;
      }
      s += "}";
      first = false;
    }
    s += "}, \"invalid\": [";
    for (std::size_t i = 0; i < invalid.size(); ++i)
      s += fmt::format("{}{{\"index\": {}, \"type\": {}, \"centroid\": [{}, {}, {}]}}", i ? ", " : "",
                       invalid[i].index, json_string(ho::to_string(invalid[i].shape)), invalid[i].centroid[0],
                       invalid[i].centroid[1], invalid[i].centroid[2]);
    s += fmt::format("], \"min_scaled_jacobian\": {}, \"median_scaled_jacobian\": {}}}\n", min_sj, median_sj);
    out << s;
  } else {
    out << path << ": " << m.elements().size() << " volume elements, " << m.boundary_faces().size()
        << " boundary faces, order " << m.order() << "\n";
    for (const auto& [type, by_order] : counts)
      for (const auto& [order, n] : by_order) out << fmt::format("  {:<14} P{}  {:>10}\n", type, order, n);
    out << "invalid elements: " << invalid.size() << "\n";
    for (const auto& bad : invalid)
      out << fmt::format("  element {} ({}) centroid ({:.6g}, {:.6g}, {:.6g})\n", bad.index, ho::to_string(bad.shape),
                         bad.centroid[0], bad.centroid[1], bad.centroid[2]);
    out << fmt::format("min scaled Jacobian: {:.6g}\nmedian scaled Jacobian: {:.6g}\n", min_sj, median_sj);
  }
  return invalid.empty() ? 0 : 2;
}

}  // namespace semimesh::io
