#include "semimesh/pipeline/pictures.hpp"

#include "semimesh/io/pictures.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace semimesh::pipeline {
namespace {

// The coordinate axis (1 or 2) closest to the wall's normal: the span's. The cuts are normal to it,
// streamwise is x. 2 when the mesh has no wall faces.
int span_axis(const mesh::Mesh& mesh) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    if (mesh.group_names()[mesh.boundary_faces()[b].group] != "wall") continue;
    const auto& v = mesh.boundary_faces()[b].vertices;
    const Eigen::Vector3d n = (mesh.node(v[1]) - mesh.node(v[0])).cross(mesh.node(v[2]) - mesh.node(v[0]));
    normal += normal.dot(n) < 0 ? -n : n;
  }
  return std::abs(normal.y()) > std::abs(normal.z()) ? 1 : 2;
}

}  // namespace

std::vector<Picture> mesh_pictures(const mesh::Mesh& mesh, const checks::ValidityResult& validity, double station) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    if (mesh.group_names()[mesh.boundary_faces()[b].group] != "wing") continue;
    for (const mesh::NodeId id : mesh.boundary_face_nodes(b)) {
      lo = lo.cwiseMin(mesh.node(id));
      hi = hi.cwiseMax(mesh.node(id));
    }
  }
  if (!(lo.x() <= hi.x())) throw std::invalid_argument("pictures: the mesh has no boundary faces of group 'wing'");
  // Span along the axis `s` (z for the analytic wing, y for the ONERA M6), thickness along `t`.
  const int s = span_axis(mesh), t = 3 - s;
  const double z = lo[s] + station * (hi[s] - lo[s]);
  // The section at the cut: its chordwise extent and its mid-thickness (from the body's faces).
  const double chord = hi.x() - lo.x(), middle = 0.5 * (lo[t] + hi[t]);
  const std::string at = fmt::format("{} = {:.4g}", s == 2 ? "z" : "y", z);
  std::vector<Picture> out;
  out.push_back({"_cut.svg", io::svg_cut(mesh, s, z,
                                         {lo.x() - 0.3 * chord, middle - 0.35 * chord, hi.x() + 0.3 * chord,
                                          middle + 0.35 * chord},
                                         "spanwise cut at " + at).svg});
  out.push_back({"_cut_le.svg", io::svg_cut(mesh, s, z,
                                            {lo.x() - 0.06 * chord, middle - 0.08 * chord, lo.x() + 0.12 * chord,
                                             middle + 0.08 * chord},
                                            "leading edge at " + at).svg});
  out.push_back({"_cut_te.svg", io::svg_cut(mesh, s, z,
                                            {hi.x() - 0.12 * chord, middle - 0.06 * chord, hi.x() + 0.12 * chord,
                                             middle + 0.06 * chord},
                                            "trailing edge at " + at).svg});
  const auto& regions = mesh.region_names();
  auto has = [&](const std::string& name) {
    const auto it = std::find(regions.begin(), regions.end(), name);
    if (it == regions.end()) return false;
    const auto index = static_cast<std::uint16_t>(it - regions.begin());
    return std::any_of(mesh.elements().begin(), mesh.elements().end(),
                       [&](const mesh::Element& e) { return e.region == index; });
  };
  if (has("junction")) {
    const double x = lo.x() + 0.4 * chord;
    // The cut normal to x shows (y, z): thickness and span, in that axis order.
    const io::Window window = s == 2 ? io::Window{middle - 0.25 * chord, lo.z(), middle + 0.25 * chord, lo.z() + 0.3 * chord}
                                     : io::Window{lo.y(), middle - 0.25 * chord, lo.y() + 0.3 * chord, middle + 0.25 * chord};
    out.push_back({"_cut_junction.svg", io::svg_cut(mesh, 0, x, window, fmt::format("root junction, cut at x = {:.4g}", x)).svg});
  }
  if (has("wake"))
    out.push_back({"_cut_wake.svg", io::svg_cut(mesh, s, z,
                                                {hi.x() - 0.3 * chord, middle - 0.3 * chord, hi.x() + 2.0 * chord,
                                                 middle + 0.3 * chord},
                                                "wake at " + at).svg});
  out.push_back({"_body_planform.svg",
                 io::svg_surface(mesh, "wing", t, fmt::format("body surface mesh seen along {}", t == 1 ? "y" : "z"))});
  out.push_back({"_body_front.svg", io::svg_surface(mesh, "wing", 0, "body surface mesh seen along x")});
  std::map<std::string, std::vector<double>> by_type;
  for (std::size_t e = 0; e < validity.scaled_jacobians.size() && e < mesh.elements().size(); ++e)
    by_type[ho::to_string(mesh.elements()[e].shape)].push_back(validity.scaled_jacobians[e]);
  out.push_back({"_quality.svg", io::svg_histogram(by_type, "scaled Jacobian per element (log counts)")});
  return out;
}

}  // namespace semimesh::pipeline
