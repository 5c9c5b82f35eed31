// A coarse NACA 0012 wing on its wall and its O-type prism shell (build_o_shell), shared by the
// high-order tests on a real near field.
#pragma once

#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "semimesh/surface/size_field.hpp"

#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace semimesh::ho::testing {

struct OShellCase {
  std::unique_ptr<cad::Model> model;
  nearfield::NearField field;
};

/// max_size: the surface mesh's largest edge (smaller: more prisms); thickness: the shell's delta.
inline OShellCase naca_o_shell(double max_size, double thickness) {
  OShellCase c;
  mock_cad::NacaWingParams wing;
  wing.span = 1.5;
  wing.sharp_te = true;  // no squared-off TE base: its thin strip would need thousands of triangles
  c.model = mock_cad::make_naca_wing(wing);
  surface::SizeParams size;
  size.max_size = max_size;
  size.min_size = 0.01;
  size.curvature_segments = 2.0;
  size.gradation = 1.5;
  size.le_size = 0.03;
  size.te_size = 0.1;
  const surface::SizeField sizes(*c.model, size);
  const surface::SurfaceMeshes meshes = surface::mesh_model_surfaces(*c.model, sizes);
  nearfield::BodyRoles roles;
  for (const std::string name : {"upper", "lower", "te_base", "tip"})
    if (auto s = c.model->find_surface(name)) roles.body_surfaces.push_back(*s);
  roles.wall_surface = c.model->find_surface("wall").value();
  nearfield::ShellParams shell;
  shell.thickness = thickness;
  c.field = nearfield::build_o_shell(*c.model, meshes, roles, shell);
  return c;
}

/// The coarse shell most tests share (max size 0.6, thickness 0.05), built once per process.
inline const OShellCase& coarse_o_shell() {
  static const OShellCase c = naca_o_shell(0.6, 0.05);
  return c;
}

inline std::vector<std::size_t> all_elements(const mesh::Mesh& m) {
  std::vector<std::size_t> all(m.elements().size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return all;
}

}  // namespace semimesh::ho::testing
