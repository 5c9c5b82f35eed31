#include "semimesh/nearfield/o_shell.hpp"

#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/layer_checks.hpp"
#include "semimesh/nearfield/node_normals.hpp"

#include "labels.hpp"
#include "shell_common.hpp"

#include <algorithm>

namespace semimesh::nearfield {

const params::Table<ShellParams>& shell_keys() {
  static const params::Table<ShellParams> table = {
      params::real("thickness", &ShellParams::thickness, "> 0", "shell thickness δ, model units"),
      params::integer("smoothing_passes", &ShellParams::normal_smoothing_passes, ">= 0",
                      "Laplacian smoothing passes of the node normals over the body mesh"),
      params::real("min_thickness_fraction", &ShellParams::min_thickness_fraction, "(0, 1]",
                   "local thickness reduction below this fraction of δ is an error"),
      params::real("reduction_factor", &ShellParams::reduction_factor, "(0, 1)",
                   "thickness multiplier per reduction round"),
      params::real("gradation", &ShellParams::gradation, "> 0",
                   "after a reduction, |δx − δy| <= gradation |x − y| between nodes x, y"),
  };
  return table;
}

NearField build_o_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params) {
  detail::check_shell_params(model, roles, params);
  const BodyMesh body = merge_body_meshes(model, meshes, roles.body_surfaces);
  const int count = body.num_nodes();
  const auto open = open_edges(body);
  const auto neighbours = node_neighbours(body);

  // Root nodes: on the body's open edges, which must all lie on the wall.
  std::vector<char> root(count, 0);
  std::vector<Vec3> plane_normal(count, Vec3::Zero());
  std::vector<cad::Vec2> wall_uv(count, cad::Vec2::Zero());  // [nodes] root nodes: (u, v) on the wall
  for (const auto& [a, b] : open)
    for (int v : {a, b}) {
      if (root[v]) continue;
      if (roles.wall_surface < 0 || !detail::on_wall(model, body.cad[v], roles.wall_surface))
        throw NearFieldError("near field: the body mesh is open at " + point_label(body.points[v]) + " on " +
                             surface_label(model, body.node_surface[v]) +
                             (roles.wall_surface < 0 ? " and no wall surface is given"
                                                     : " away from the wall " + surface_label(model, roles.wall_surface)) +
                             "; list every surface of the body");
      const cad::Surface& wall = model.surface(roles.wall_surface);
      root[v] = 1;
      wall_uv[v] = wall.project(body.points[v]).uv;
      plane_normal[v] = wall.normal(wall_uv[v]);
    }

  NormalOptions normal_options;
  normal_options.smoothing_passes = params.normal_smoothing_passes;
  const std::vector<Vec3> normals = node_normals(body, plane_normal, normal_options);

  detail::OffsetConstraints constraints{root, wall_uv, roles.wall_surface, {}, {}};
  const detail::LayerOffsets offsets = detail::offset_body_nodes(model, body, neighbours, normals, constraints, params);
  const std::vector<Vec3>& outer = offsets.outer;
  const std::vector<cad::Vec2>& outer_wall_uv = offsets.outer_wall_uv;

  NearField field;
  field.warnings = offsets.warnings;
  mesh::Mesh& m = field.mesh;
  m.reserve(ho::Shape::Prism, body.triangles.size());
  const int layer_region = m.region_index("wing_layer");
  for (int i = 0; i < count; ++i) m.add_node(body.points[i], body.cad[i]);
  const auto offset = static_cast<mesh::NodeId>(count);
  for (int i = 0; i < count; ++i) {
    mesh::CadAttachment cad;
    if (root[i]) cad = {mesh::CadAttachment::Surface, roles.wall_surface, outer_wall_uv[i].x(), outer_wall_uv[i].y()};
    m.add_node(outer[i], cad);
  }
  auto id = [](int v) { return static_cast<mesh::NodeId>(v); };
  for (std::size_t t = 0; t < body.triangles.size(); ++t) {
    const auto& v = body.triangles[t];
    m.add_element(ho::Shape::Prism, {id(v[0]), id(v[1]), id(v[2]), id(v[0]) + offset, id(v[1]) + offset, id(v[2]) + offset},
                  layer_region);
    field.stacks.push_back({field.element_surface.size(), {LayerDirection{2, LayerFamily::Wing}}});
    field.element_surface.push_back(body.triangle_surface[t]);
    m.add_boundary_face("wing", ho::Shape::Triangle, {id(v[0]), id(v[2]), id(v[1])});
    field.skin.push_back({{id(v[0]) + offset, id(v[1]) + offset, id(v[2]) + offset, mesh::kNoNode}, 3});
  }
  for (const auto& [a, b] : open)
    m.add_boundary_face("wall", ho::Shape::Quadrilateral, {id(a), id(b), id(b) + offset, id(a) + offset});
  field.footprint = detail::footprint_loop(body, open, offset);

  field.thickness_min = params.thickness;
  field.thickness_max = 0.0;
  for (int i = 0; i < count; ++i) {
    const double used = (outer[i] - body.points[i]).norm();
    field.thickness_min = std::min(field.thickness_min, used);
    field.thickness_max = std::max(field.thickness_max, used);
  }
  return field;
}

}  // namespace semimesh::nearfield
