#include "naca_o_shell.hpp"

#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "semimesh/surface/size_field.hpp"

namespace semimesh::bench {

NacaOShell naca_o_shell() {
  mock_cad::NacaWingParams wing;
  wing.span = 1.5;
  wing.sharp_te = true;
  NacaOShell shell{mock_cad::make_naca_wing(wing), mesh::Mesh(1)};
  surface::SizeParams size;
  size.max_size = 0.6;
  size.min_size = 0.01;
  size.curvature_segments = 2.0;
  size.gradation = 1.5;
  size.le_size = 0.03;
  size.te_size = 0.1;
  const surface::SurfaceMeshes meshes = surface::mesh_model_surfaces(*shell.model, surface::SizeField(*shell.model, size));
  nearfield::BodyRoles roles;
  for (const char* name : {"upper", "lower", "tip"}) roles.body_surfaces.push_back(*shell.model->find_surface(name));
  roles.wall_surface = *shell.model->find_surface("wall");
  shell.linear = nearfield::build_o_shell(*shell.model, meshes, roles, {}).mesh;
  return shell;
}

}  // namespace semimesh::bench
