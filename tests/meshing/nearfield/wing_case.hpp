// The near-field tests' wings: coarse surface meshes of an analytic NACA wing on its wall, with
// the body (upper, lower, te_base when blunt, tip) and the wall as roles; the base meshed with
// structured quads when asked (as the H-type needs).
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <memory>
#include <string>

namespace semimesh::nearfield::testing {

struct WingCase {
  std::unique_ptr<cad::Model> model;
  surface::SurfaceMeshes meshes;
  BodyRoles roles;
};

inline WingCase wing_case(const mock_cad::NacaWingParams& wing, double max_size = 0.4, bool structured_base = false) {
  WingCase c;
  c.model = mock_cad::make_naca_wing(wing);
  surface::SizeParams size;
  size.max_size = max_size;
  size.min_size = 0.01;
  size.curvature_segments = 2.0;
  size.gradation = 1.3;
  size.le_size = 0.04;
  size.te_size = 0.04;
  const surface::SizeField field(*c.model, size);
  surface::ModelMeshOptions options;
  if (structured_base && c.model->find_surface("te_base")) options.structured_surfaces.insert(*c.model->find_surface("te_base"));
  c.meshes = surface::mesh_model_surfaces(*c.model, field, options);
  for (const std::string name : {"upper", "lower", "te_base", "tip"})
    if (auto s = c.model->find_surface(name)) c.roles.body_surfaces.push_back(*s);
  c.roles.wall_surface = c.model->find_surface("wall").value();
  return c;
}

inline mock_cad::NacaWingParams naca(const std::string& code, bool sharp, double taper = 1.0, double sweep = 0.0) {
  mock_cad::NacaWingParams p;
  p.code = code;
  p.sharp_te = sharp;
  p.taper = taper;
  p.sweep_deg = sweep;
  p.span = 1.5;
  return p;
}

/// The id of the model's curve called `name`, -1 when there is none.
inline int curve_named(const cad::Model& model, const std::string& name) {
  for (int c = 0; c < model.num_curves(); ++c)
    if (model.curve(c).name() == name) return c;
  return -1;
}

/// Elements whose straight-sided (vertex) map is not certified valid.
inline int invalid_elements(const mesh::Mesh& m) {
  int invalid = 0;
  for (const mesh::Element& e : m.elements()) {
    const int n = ho::num_vertices(e.shape);
    Eigen::MatrixX3d x(n, 3);
    for (int k = 0; k < n; ++k) x.row(k) = m.node(e.vertices[k]).transpose();
    invalid += ho::certify_jacobian(e.shape, 1, ho::NodeSet::Equispaced, x).valid ? 0 : 1;
  }
  return invalid;
}

}  // namespace semimesh::nearfield::testing
