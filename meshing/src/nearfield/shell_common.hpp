// What the O-type and C-type shells share: parameter checks, the root test, the offset of the body
// nodes with local thickness reduction, the warnings about reductions and the footprint loop.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/near_field.hpp"
#include "semimesh/nearfield/o_shell.hpp"

#include <string>
#include <utility>
#include <vector>

namespace semimesh::nearfield::detail {

/// Throws NearFieldError naming the parameter or surface that is out of range.
void check_shell_params(const cad::Model& model, const BodyRoles& roles, const ShellParams& params);

/// Whether a body node's CAD attachment (its curve, or a curve of its vertex) bounds `wall`.
bool on_wall(const cad::Model& model, const mesh::CadAttachment& cad, int wall);

/// Where each body node's layer ends.
///  root   [nodes] offsets projected onto the wall (O-type root nodes; wall_uv their (u, v) there)
///  pinned [nodes] offsets given (C-type: the halo above the top of the root strip); never reduced
struct OffsetConstraints {
  std::vector<char> root;
  std::vector<cad::Vec2> wall_uv;
  int wall_surface = -1;
  std::vector<char> pinned;
  std::vector<Vec3> pinned_outer;
};

struct LayerOffsets {
  std::vector<Vec3> outer;               ///< [nodes]
  std::vector<cad::Vec2> outer_wall_uv;  ///< [nodes] root nodes: (u, v) of the offset on the wall
  std::vector<double> thickness;         ///< [nodes] after reduction
  std::vector<Warning> warnings;         ///< one per reduced region
};

/// The layer cannot be built at body node `node` (its message names the place).
class LayerFoldError : public NearFieldError {
 public:
  LayerFoldError(const std::string& message, int node, std::string reason)
      : NearFieldError(message), node(node), reason(std::move(reason)) {}
  int node;
  std::string reason;  ///< what the layer check found there (reason_text)
};

/// Offsets x + thickness n along the node normals, reducing the thickness where prisms would fold
/// or the layer would crowd another part of the body (see o_shell.hpp). Throws LayerFoldError.
LayerOffsets offset_body_nodes(const cad::Model& model, const BodyMesh& body,
                               const std::vector<std::vector<int>>& neighbours, const std::vector<Vec3>& normals,
                               const OffsetConstraints& constraints, const ShellParams& params);

/// The skin's edges on the wall, (a', b') as in their skin face, chained into one loop of body
/// nodes plus `outer_offset`. Throws NearFieldError when they do not form one simple loop.
std::vector<mesh::NodeId> footprint_loop(const BodyMesh& body, const std::vector<std::pair<int, int>>& open,
                                         mesh::NodeId outer_offset);

}  // namespace semimesh::nearfield::detail
