#include "semimesh/farfield/detail/symmetry_faces.hpp"

#include "semimesh/farfield/far_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace semimesh::farfield {

int move_symmetry_faces(mesh::Mesh& mesh, const std::string& side, double tolerance) {
  const auto known = std::find(std::begin(kSymmetrySides), std::end(kSymmetrySides), side);
  if (known == std::end(kSymmetrySides))
    throw FarFieldError(fmt::format("far field: farfield.symmetry = \"{}\" is not a side of the far field "
                                    "(xmin, xmax, ymin, ymax, zmin or zmax)",
                                    side));
  const int axis = static_cast<int>(known - std::begin(kSymmetrySides)) / 2;
  const double sign = side.substr(1) == "max" ? 1.0 : -1.0;
  const auto& groups = mesh.group_names();
  const auto farfield = std::find(groups.begin(), groups.end(), "farfield");
  const int group = farfield == groups.end() ? -1 : static_cast<int>(farfield - groups.begin());
  const auto& faces = mesh.boundary_faces();
  auto each_vertex = [&](const mesh::BoundaryFace& f, auto&& visit) {
    const int nv = f.shape == ho::Shape::Triangle ? 3 : 4;
    for (int k = 0; k < nv; ++k) visit(mesh.node(f.vertices[k])[axis]);
  };
  // The plane: the far field's farthest coordinate that way (sign * x greatest).
  double extreme = -std::numeric_limits<double>::infinity();
  for (const mesh::BoundaryFace& f : faces)
    if (f.group == group) each_vertex(f, [&](double x) { extreme = std::max(extreme, sign * x); });
  int moved = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i].group != group) continue;
    bool on_plane = true;
    each_vertex(faces[i], [&](double x) { on_plane = on_plane && std::abs(sign * x - extreme) <= tolerance; });
    if (!on_plane) continue;
    mesh.set_boundary_group(i, "symmetry");
    ++moved;
  }
  if (moved == 0)
    throw FarFieldError(fmt::format("far field: farfield.symmetry = \"{}\": no far-field face lies on the plane "
                                    "{} = {:.6g} (a symmetry plane must be a flat side of a box far field)",
                                    side, "xyz"[axis], sign * extreme));
  return moved;
}

}  // namespace semimesh::farfield
