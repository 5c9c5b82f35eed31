#include "check_command.hpp"

#include "exit_codes.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/io/json.hpp"
#include "semimesh/io/msh.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <exception>
#include <map>

namespace semimesh::app {

int run_check_command(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  mesh::Mesh m;
  try {
    m = io::read_msh(options.mesh);
  } catch (const std::exception& e) {
    fmt::print(err, "semimesh check: {}\n", e.what());
    return kExitBadInput;
  }
  const ho::MeshValidity validity = ho::certify_mesh(m);

  std::map<std::string, std::map<int, std::size_t>> counts;
  for (const mesh::Element& e : m.elements()) ++counts[ho::to_string(e.shape)][m.order()];
  for (const mesh::BoundaryFace& b : m.boundary_faces()) ++counts[ho::to_string(b.shape)][m.order()];

  if (options.json) {
    std::string s = "{\"file\": " + io::json_string(options.mesh) + ", \"elements\": {";
    bool first = true;
    for (const auto& [type, by_order] : counts) {
      s += fmt::format("{}{}: {{", first ? "" : ", ", io::json_string(type));
      bool first_order = true;
      for (const auto& [order, n] : by_order) {
        s += fmt::format("{}\"{}\": {}", first_order ? "" : ", ", order, n);
        first_order = false;
      }
      s += "}";
      first = false;
    }
    s += "}, \"invalid\": [";
    for (std::size_t i = 0; i < validity.invalid_elements.size(); ++i) {
      const std::size_t e = validity.invalid_elements[i];
      const Eigen::Vector3d& c = validity.invalid_centroids[i];
      s += fmt::format("{}{{\"index\": {}, \"type\": {}, \"centroid\": [{}, {}, {}]}}", i ? ", " : "", e,
                       io::json_string(ho::to_string(m.elements()[e].shape)), io::json_number(c.x()),
                       io::json_number(c.y()), io::json_number(c.z()));
    }
    s += fmt::format("], \"min_scaled_jacobian\": {}, \"median_scaled_jacobian\": {}}}\n",
                     io::json_number(validity.min_scaled_jacobian), io::json_number(validity.median_scaled_jacobian));
    out << s;
  } else {
    fmt::print(out, "{}: {} volume elements, {} boundary faces, order {}\n", options.mesh, m.elements().size(),
               m.boundary_faces().size(), m.order());
    for (const auto& [type, by_order] : counts)
      for (const auto& [order, n] : by_order) fmt::print(out, "  {:<14} P{}  {:>10}\n", type, order, n);
    fmt::print(out, "invalid elements: {}\n", validity.invalid);
    for (std::size_t i = 0; i < validity.invalid_elements.size(); ++i) {
      const Eigen::Vector3d& c = validity.invalid_centroids[i];
      fmt::print(out, "  element {} ({}) centroid ({:.6g}, {:.6g}, {:.6g})\n", validity.invalid_elements[i],
                 ho::to_string(m.elements()[validity.invalid_elements[i]].shape), c.x(), c.y(), c.z());
    }
    fmt::print(out, "min scaled Jacobian: {:.6g}\nmedian scaled Jacobian: {:.6g}\n", validity.min_scaled_jacobian,
               validity.median_scaled_jacobian);
  }
  return validity.all_valid() ? kExitOk : kExitInvalidMesh;
}

}  // namespace semimesh::app
