#include "semimesh/farfield/far_field.hpp"

#include "semimesh/cad/labels.hpp"

#include "semimesh/farfield/detail/interior_points.hpp"
#include "semimesh/farfield/detail/pyramid_apex.hpp"
#include "semimesh/farfield/detail/symmetry_faces.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mesh/directed_edge_index.hpp"
#include "semimesh/nearfield/pyramid_apex.hpp"
#include "tetgen_volume.hpp"
#include "semimesh/farfield/detail/wall_annulus.hpp"
#include "wall_layer.hpp"
#include "../surface/boundary_nodes.hpp"

#include "semimesh/surface/curve_discretisation.hpp"
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/surface_mesh.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace semimesh::farfield {

const params::Table<FarFieldParams>& far_field_keys() {
  static const params::Table<FarFieldParams> table = {
      params::real("box_size", &FarFieldParams::box_size, "> 0", "edge length on the box faces, model units"),
      params::real("wall_size", &FarFieldParams::wall_size, "> 0", "edge length on the wall far from the body"),
      params::real("growth", &FarFieldParams::growth, ">= 1", "size gradation from the skin outwards"),
      params::real("radius_edge_ratio", &FarFieldParams::radius_edge_ratio, ">= 1",
                   "TetGen quality bound (-q) of its refinement after the interior points; 1.5 to 2 is usual"),
      params::real("max_volume", &FarFieldParams::max_volume, ">= 0", "TetGen volume bound (-a); 0: none"),
      params::string("symmetry", &FarFieldParams::symmetry,
                     "\"none\" | \"xmin\" | \"xmax\" | \"ymin\" | \"ymax\" | \"zmin\" | \"zmax\"",
                     "a half model: the box's side on the plane of symmetry, whose faces (the wall layer's "
                     "where it meets it too) go to boundary group \"symmetry\"; none: all are \"farfield\""),
  };
  return table;
}

namespace {

using mesh::CadAttachment;
using mesh::NodeId;

void check_params(const cad::Model& model, const nearfield::NearField& nf, const FarFieldParams& p,
                  const std::vector<int>& box_surfaces, int wall_surface) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw FarFieldError("far field: " + what);
  };
  if (const auto bad = params::violation(p, far_field_keys(), "farfield")) require(false, *bad);
  require(nf.mesh.order() == 1, "the near-field mesh must be linear (order 1) when the far field is built, it has order " +
                                    std::to_string(nf.mesh.order()));
  require(nf.footprint.size() >= 3, "the near field's footprint has " + std::to_string(nf.footprint.size()) +
                                        " nodes; a closed loop needs at least 3");
  require(!box_surfaces.empty(), "no box surfaces given");
  for (int s : box_surfaces)
    require(s >= 0 && s < model.num_surfaces(), "box surface id " + std::to_string(s) + " is not a surface of the model");
  require(wall_surface >= 0 && wall_surface < model.num_surfaces(),
          "wall surface id " + std::to_string(wall_surface) + " is not a surface of the model");
}

// One mesh node per CAD vertex and per inner curve-mesh node, so every surface using a curve
// shares its nodes.
class CurveNodes {
 public:
  CurveNodes(const cad::Model& model, const surface::CurveMeshes& curves, mesh::Mesh& mesh)
      : model_(model), curves_(curves), mesh_(mesh) {}

  int segments(int curve) const { return curves_.at(curve).segments(); }

  NodeId node(int curve, int index) {
    const surface::CurveMesh& cm = curves_.at(curve);
    if (index == 0 || index == cm.segments()) {
      const int vertex = model_.curve_vertices(curve)[index == 0 ? 0 : 1];
      auto [it, added] = by_vertex_.try_emplace(vertex, mesh::kNoNode);
      if (added) it->second = mesh_.add_node(cm.points[index], {CadAttachment::Vertex, vertex});
      return it->second;
    }
    auto [it, added] = by_curve_node_.try_emplace({curve, index}, mesh::kNoNode);
    if (added) it->second = mesh_.add_node(cm.points[index], {CadAttachment::Curve, curve, cm.t[index]});
    return it->second;
  }

 private:
  const cad::Model& model_;
  const surface::CurveMeshes& curves_;
  mesh::Mesh& mesh_;
  std::map<int, NodeId> by_vertex_;
  std::map<std::pair<int, int>, NodeId> by_curve_node_;
};

// Box faces but `skip` (-1: none), meshed on the CAD; triangles returned with their normal out of the domain.
std::vector<Triangle> mesh_box(const cad::Model& model, const std::vector<int>& box_surfaces, int skip,
                               const surface::CurveMeshes& curves, const surface::SizeField& size, CurveNodes& curve_nodes,
                               mesh::Mesh& mesh) {
  std::vector<Triangle> triangles;
  for (int s : box_surfaces) {
    if (s == skip) continue;
    surface::SurfaceMesh sm;
    try {
      sm = surface::mesh_surface(model, s, curves, size);
    } catch (const surface::SurfaceMeshError& e) {
      throw FarFieldError("far field: meshing box surface " + std::to_string(s) + " ('" + model.surface(s).name() +
                          "') failed: " + e.what());
    }
    if (!sm.quads.empty())
      throw FarFieldError("far field: box surface " + std::to_string(s) + " was meshed with quads; triangles expected");
    std::vector<NodeId> ids(sm.num_nodes());
    for (int i = 0; i < sm.num_nodes(); ++i)
      ids[i] = sm.origin[i].on_boundary()
                   ? curve_nodes.node(sm.origin[i].curve, sm.origin[i].index)
                   : mesh.add_node(sm.points[i], {CadAttachment::Surface, s, sm.uv[i].x(), sm.uv[i].y()});
    // The surface mesh faces the fluid (into the box); the boundary faces face out of it.
    for (const auto& t : sm.triangles) triangles.push_back({ids[t[0]], ids[t[2]], ids[t[1]]});
  }
  return triangles;
}

// The nodes round a surface's first (outer) loop, in the loop's order.
std::vector<NodeId> outer_loop_nodes(const cad::Model& model, int surface, CurveNodes& curve_nodes) {
  std::vector<NodeId> ids;
  for (const cad::CurveUse& use : model.loops(surface).front().uses) {
    const int n = curve_nodes.segments(use.curve);
    for (int k = 0; k < n; ++k) ids.push_back(curve_nodes.node(use.curve, use.forward ? k : n - k));
  }
  return ids;
}

// An orthonormal frame of the wall plane with e1 x e2 = the wall's fluid normal.
struct PlaneFrame {
  Eigen::Vector3d origin, e1, e2, normal;
  Eigen::Vector2d to_2d(const Eigen::Vector3d& x) const { return {(x - origin).dot(e1), (x - origin).dot(e2)}; }
  Eigen::Vector3d to_3d(const Eigen::Vector2d& a) const { return origin + a.x() * e1 + a.y() * e2; }
};

PlaneFrame wall_frame(const cad::Surface& wall) {
  const auto bounds = wall.bounds();
  const cad::Vec2 mid(0.5 * (bounds[0].lo + bounds[0].hi), 0.5 * (bounds[1].lo + bounds[1].hi));
  PlaneFrame f;
  f.origin = wall.point(mid);
  f.normal = wall.normal(mid);
  const Eigen::Vector3d helper = std::abs(f.normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  f.e1 = f.normal.cross(helper).normalized();
  f.e2 = f.normal.cross(f.e1);
  return f;
}

// Puts the wall's outer loop in an order that does not depend on the CAD backend's loop start and
// direction: counter-clockwise in the wall frame, starting at the lowest (x, y) node (compared on
// rounded coordinates so 1e-13 differences between backends do not change the start). The annulus
// triangulation, and so TetGen's input, then comes out the same for equivalent models.
void canonicalise_outer_loop(std::vector<NodeId>& ids, const PlaneFrame& frame, const mesh::Mesh& mesh) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Eigen::Vector2d p = frame.to_2d(mesh.node(ids[i])), q = frame.to_2d(mesh.node(ids[(i + 1) % ids.size()]));
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  if (twice_area < 0) std::reverse(ids.begin(), ids.end());
  auto key = [&](NodeId id) {
    const Eigen::Vector2d p = frame.to_2d(mesh.node(id));
    return std::make_pair(std::round(p.x() * 1e8), std::round(p.y() * 1e8));
  };
  std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end(), [&](NodeId a, NodeId b) { return key(a) < key(b); }),
              ids.end());
}

// The annulus's own points (after its loops', whose nodes `ids` holds) added as nodes on the planar
// surface `surface`, appended to `ids`.
void add_annulus_points(const Annulus& annulus, const PlaneFrame& frame, const cad::Model& model, int surface,
                        std::vector<NodeId>& ids, mesh::Mesh& mesh) {
  const cad::Surface& face = model.surface(surface);
  for (std::size_t i = ids.size(); i < annulus.points.size(); ++i) {
    const Eigen::Vector3d x = frame.to_3d(annulus.points[i]);
    const cad::SurfaceProjection on_face = face.project(x);
    ids.push_back(mesh.add_node(x, {CadAttachment::Surface, surface, on_face.uv.x(), on_face.uv.y()}));
  }
}

// The far-field part of a planar wall, triangulated in the plane; triangles returned with their
// normal out of the domain.
std::vector<Triangle> mesh_planar_wall(const cad::Model& model, int wall_surface, const nearfield::NearField& nf,
                                       const FarFieldParams& params, CurveNodes& curve_nodes, mesh::Mesh& mesh) {
  const cad::Surface& wall = model.surface(wall_surface);
  const PlaneFrame frame = wall_frame(wall);

  std::vector<NodeId> ids = outer_loop_nodes(model, wall_surface, curve_nodes);
  std::vector<Eigen::Vector2d> outer, hole;
  canonicalise_outer_loop(ids, frame, mesh);
  for (NodeId id : ids) outer.push_back(frame.to_2d(mesh.node(id)));

  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());
  for (NodeId id : nf.footprint) {
    const Eigen::Vector3d& x = mesh.node(id);
    const double off = (x - frame.origin).dot(frame.normal);
    if (std::abs(off) > 10 * tolerance)
      throw FarFieldError("far field: footprint node " + std::to_string(id) + " lies " + std::to_string(off) +
                          " off the plane of wall surface " + std::to_string(wall_surface));
    hole.push_back(frame.to_2d(x));
    ids.push_back(id);
  }

  const Annulus annulus = triangulate_annulus(outer, hole, params.wall_size, params.growth);
  add_annulus_points(annulus, frame, model, wall_surface, ids, mesh);
  std::vector<Triangle> triangles;
  // Counter-clockwise in (e1, e2) means along the fluid normal: reversed to face out of the domain.
  for (const auto& t : annulus.triangles) triangles.push_back({ids[t[0]], ids[t[2]], ids[t[1]]});
  return triangles;
}

// The far field's face that holds the wake block's outflow face (an H-type's wake run to it: the
// near field's outlet outline): the planar box face every outline node lies on.
int outlet_surface(const cad::Model& model, const std::vector<int>& box_surfaces, const nearfield::NearField& nf,
                   double tolerance) {
  for (int s : box_surfaces) {
    if (!model.surface(s).is_planar()) continue;
    const PlaneFrame frame = wall_frame(model.surface(s));
    if (std::all_of(nf.outlet.begin(), nf.outlet.end(), [&](NodeId v) {
          return std::abs((nf.mesh.node(v) - frame.origin).dot(frame.normal)) <= 10 * tolerance;
        }))
      return s;
  }
  const Eigen::Vector3d& x = nf.mesh.node(nf.outlet.front());
  throw FarFieldError(fmt::format("far field: the wake block runs to the far field's downstream face (output.target = "
                                  "\"pyfr\"), but no planar far-field surface holds its outflow face (node {} at "
                                  "({:.6g}, {:.6g}, {:.6g}))",
                                  nf.outlet.front(), x.x(), x.y(), x.z()));
}

// The outlet face (outlet_surface) triangulated in its plane between its outer loop `outline`
// (lifted onto the wall layer's tops) and the wake's outflow face; triangles returned with their
// normal out of the domain (away from the model's centre).
std::vector<Triangle> mesh_outlet(const cad::Model& model, int surface, const std::vector<NodeId>& outline,
                                  const nearfield::NearField& nf, const FarFieldParams& params, mesh::Mesh& mesh) {
  const cad::Surface& face = model.surface(surface);
  const PlaneFrame frame = wall_frame(face);
  std::vector<NodeId> ids = outline;
  std::vector<Eigen::Vector2d> outer, hole;
  for (NodeId id : outline) outer.push_back(frame.to_2d(mesh.node(id)));
  for (NodeId id : nf.outlet) {
    hole.push_back(frame.to_2d(mesh.node(id)));
    ids.push_back(id);
  }
  const Annulus annulus = triangulate_annulus(outer, hole, params.box_size, params.growth);
  add_annulus_points(annulus, frame, model, surface, ids, mesh);
  const cad::BBox box = model.bbox();
  const bool along_normal_is_out = (frame.origin - 0.5 * (box.lo + box.hi)).dot(frame.normal) > 0;
  std::vector<Triangle> triangles;
  for (const auto& t : annulus.triangles)
    triangles.push_back(along_normal_is_out ? Triangle{ids[t[0]], ids[t[1]], ids[t[2]]}
                                            : Triangle{ids[t[0]], ids[t[2]], ids[t[1]]});
  return triangles;
}

// Segments per radian of turning on a curved wall and its curves: the near field's default
// (sizing.curvature_segments), so a far-field triangle's chord stays within 3 % of its size off
// the wall and the tets on it keep their shape once curved onto it.
constexpr double kCurvedWallSegments = 4.0;

// Under a wall layer (straight-topped prisms on the curved wall, split isoparametrically) an edge
// of turning angle t on a radius R dips R (1 - cos(t / 2)) ~ R t^2 / 8 below the layer's top's
// chord: at most this fraction of the layer's thickness. At a quarter radian on a fuselage 44
// layer thicknesses round (OpenVSP's transport at 0.02 ft) that was a third, and every wall-layer
// prism along the box's ends folded at order 4; at 0.15 they are valid (0.48). Not less: a tenth
// changed the examples' walls (1.5 chords under 0.1), which a quarter radian serves.
constexpr double kWallLayerDip = 0.15;

// The wall's parameters of the near field's footprint nodes: their own where the near field
// attached them to the wall, else projected, each from its predecessor's.
std::vector<cad::Vec2> footprint_uvs(const cad::Model& model, int wall_surface, const nearfield::NearField& nf,
                                     const mesh::Mesh& mesh) {
  if (nf.footprint.empty()) throw FarFieldError("far field: the near field has no footprint on the wall");
  const cad::Surface& wall = model.surface(wall_surface);
  std::vector<cad::Vec2> uvs;
  cad::Vec2 guess = wall.project(mesh.node(nf.footprint.front())).uv;
  for (NodeId id : nf.footprint) {
    const CadAttachment cad = mesh.cad_attachment(id);
    guess = cad.kind == CadAttachment::Surface && cad.entity == wall_surface ? cad::Vec2(cad.u, cad.v)
                                                                             : wall.project(mesh.node(id), guess).uv;
    uvs.push_back(guess);
  }
  return uvs;
}

// Segments per radian on the curved wall: kCurvedWallSegments, more under a wall layer of
// `thickness` where the wall's radius at the body's root (a fuselage's, a hub's) is large against it.
// The root's radius, not the whole surface's: a nearly flat part of a fuselage far from the wing
// would refine the whole wall.
double curved_wall_segments(const cad::Model& model, int wall_surface, const nearfield::NearField& nf,
                            const mesh::Mesh& mesh, double thickness) {
  if (!(thickness > 0.0)) return kCurvedWallSegments;
  const cad::Surface& wall = model.surface(wall_surface);
  double largest_radius = 0.0;
  for (const cad::Vec2& uv : footprint_uvs(model, wall_surface, nf, mesh)) {
    const cad::PrincipalCurvatures k = wall.curvatures(uv);
    const double kappa = std::max(std::abs(k.k_min), std::abs(k.k_max));
    if (kappa > 0.0) largest_radius = std::max(largest_radius, 1.0 / kappa);
  }
  return std::max(kCurvedWallSegments, std::sqrt(largest_radius / (8.0 * kWallLayerDip * thickness)));
}

// The far-field part of a curved wall (a fuselage, a hub), triangulated in the wall's parameter
// plane scaled to lengths at the root, (u |S_u|, v |S_v|), which is exact on a cylinder or cone's
// developable chart and close to it near the root elsewhere. The outer loops come from the surface
// mesher's boundary (a periodic wall cut open along its seam, whose nodes appear twice); the hole is
// the near field's footprint, whose nodes the near field attached to the wall. Triangles returned
// with their normal out of the domain.
std::vector<Triangle> mesh_curved_wall(const cad::Model& model, int wall_surface, const nearfield::NearField& nf,
                                       const FarFieldParams& params, double segments_per_radian,
                                       const surface::CurveMeshes& curves, CurveNodes& curve_nodes, mesh::Mesh& mesh) {
  const cad::Surface& wall = model.surface(wall_surface);
  const std::vector<cad::Vec2> hole_uv = footprint_uvs(model, wall_surface, nf, mesh);

  const cad::Vec2 root_uv = hole_uv.front();
  const cad::SurfaceDerivatives d = wall.derivatives(root_uv);
  const Eigen::Vector2d scale(d.du.norm(), d.dv.norm());
  // Counter-clockwise in the chart is along S_u x S_v: into the fluid when the wall's normal agrees.
  const bool chart_faces_fluid = d.du.cross(d.dv).dot(wall.normal(root_uv)) > 0;
  auto to_chart = [&](const cad::Vec2& uv) { return Eigen::Vector2d(uv.x() * scale.x(), uv.y() * scale.y()); };

  surface::SurfaceMesh boundary;
  std::vector<std::vector<int>> loops;
  try {
    loops = surface::detail::add_boundary_nodes(model, wall_surface, curves, boundary);
  } catch (const surface::SurfaceMeshError& e) {
    throw FarFieldError("far field: the wall " + cad::surface_label(model, wall_surface) + ": " + e.what());
  }
  if (model.loops(wall_surface).size() != 2)
    throw FarFieldError(fmt::format("far field: the curved wall {} has {} loops; the far field meshes a curved wall "
                                    "with one outer loop and the body's root as its one hole",
                                    cad::surface_label(model, wall_surface), model.loops(wall_surface).size()));
  std::vector<NodeId> ids;
  std::vector<Eigen::Vector2d> outer, hole;
  for (int i : loops.front()) {
    const surface::NodeOrigin& o = boundary.origin[i];
    ids.push_back(curve_nodes.node(o.curve, o.index));
    outer.push_back(to_chart(boundary.uv[i]));
  }
  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());
  for (std::size_t i = 0; i < nf.footprint.size(); ++i) {
    const NodeId id = nf.footprint[i];
    const double off = (mesh.node(id) - wall.point(hole_uv[i])).norm();
    if (off > 10 * tolerance)
      throw FarFieldError(fmt::format("far field: footprint node {} lies {:.3g} off the wall {}", id, off,
                                      cad::surface_label(model, wall_surface)));
    hole.push_back(to_chart(hole_uv[i]));
    ids.push_back(id);
  }

  // Edges turn by at most 1 / segments_per_radian radians on the wall, as the curve meshes do.
  double kappa = 0.0;
  for (const std::vector<cad::Vec2>* uvs : {&std::as_const(boundary.uv), &hole_uv})
    for (const cad::Vec2& uv : *uvs) {
      const cad::PrincipalCurvatures k = wall.curvatures(uv);
      kappa = std::max({kappa, std::abs(k.k_min), std::abs(k.k_max)});
    }
  const double max_size = kappa > 0 ? std::min(params.wall_size, 1.0 / (segments_per_radian * kappa)) : params.wall_size;
  const Annulus annulus = triangulate_annulus(outer, hole, max_size, params.growth);
  for (std::size_t i = ids.size(); i < annulus.points.size(); ++i) {
    const cad::Vec2 uv(annulus.points[i].x() / scale.x(), annulus.points[i].y() / scale.y());
    ids.push_back(mesh.add_node(wall.point(uv), {CadAttachment::Surface, wall_surface, uv.x(), uv.y()}));
  }
  std::vector<Triangle> triangles;
  for (const auto& t : annulus.triangles)
    triangles.push_back(chart_faces_fluid ? Triangle{ids[t[0]], ids[t[2]], ids[t[1]]}
                                          : Triangle{ids[t[0]], ids[t[1]], ids[t[2]]});
  return triangles;
}

constexpr double kPi = 3.14159265358979323846;

// The slope caps of skin quad `q`'s pyramid (nearfield::pyramid_apex): over each edge where the
// neighbouring skin face closes in on the quad's side at a far-field angle theta < 180 degrees,
// tan(0.45 theta). Two pyramids across that edge then keep a tenth of the wedge between them: at a
// right angle the caps leave the usual heights alone, but behind a tapered wing the trailing edge
// leans forward under the wake block and the corner between the block's underside and the rear
// interfaces below it closes to ~60 degrees, where the usual heights crossed (TetGen aborted).
// The skin faces by their directed edges.
mesh::DirectedEdgeIndex skin_edges(const std::vector<nearfield::SkinFace>& skin) {
  mesh::DirectedEdgeIndex edges;
  for (std::size_t f = 0; f < skin.size(); ++f)
    for (int k = 0; k < skin[f].count; ++k) edges.add(skin[f].nodes[k], skin[f].nodes[(k + 1) % skin[f].count], f);
  edges.sort();
  return edges;
}

std::array<double, 4> slope_caps(const nearfield::NearField& nf, const mesh::Mesh& mesh, std::size_t q,
                                 const mesh::DirectedEdgeIndex& face_of_edge) {
  auto centre = [&](const nearfield::SkinFace& f) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < f.count; ++k) c += mesh.node(f.nodes[k]);
    return Eigen::Vector3d(c / f.count);
  };
  auto unit_normal = [&](const nearfield::SkinFace& f) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int k = 0; k < f.count; ++k) n += mesh.node(f.nodes[k]).cross(mesh.node(f.nodes[(k + 1) % f.count]));
    return Eigen::Vector3d(n.normalized());
  };
  const nearfield::SkinFace& face = nf.skin[q];
  const Eigen::Vector3d n = unit_normal(face);
  std::array<double, 4> caps = nearfield::kNoSlopeCap;
  for (int k = 0; k < 4; ++k) {
    const NodeId a = face.nodes[k], b = face.nodes[(k + 1) % 4];
    const std::optional<std::size_t> neighbour = face_of_edge.find(b, a);  // runs the shared edge the other way
    if (!neighbour) continue;
    const nearfield::SkinFace& other = nf.skin[*neighbour];
    const Eigen::Vector3d m = 0.5 * (mesh.node(a) + mesh.node(b));
    if (!((centre(other) - m).dot(n) > 0.0)) continue;  // convex or flat: nothing closes in
    const double between_normals = std::acos(std::clamp(n.dot(unit_normal(other)), -1.0, 1.0));
    caps[k] = std::tan(0.45 * (kPi - between_normals));
  }
  return caps;
}

// A pyramid cap_skin stood on a skin quad: its apex node and base.
struct SkinPyramid {
  NodeId apex;
  std::array<NodeId, 4> base;
};

// Each skin quad becomes a pyramid (listed in `pyramids`); returns the far field's view of the
// skin: the skin triangles and the pyramids' four side triangles.
std::vector<Triangle> cap_skin(const nearfield::NearField& nf, mesh::Mesh& mesh, std::vector<SkinPyramid>& pyramids) {
  for (const nearfield::SkinFace& face : nf.skin)
    if (face.count != 3 && face.count != 4)
      throw FarFieldError("far field: a skin face has " + std::to_string(face.count) + " nodes; 3 or 4 expected");
  // The apexes first, each quad's on its own (they read the skin's nodes only), on every thread;
  // then the nodes and pyramids in skin order.
  const mesh::DirectedEdgeIndex face_of_edge = skin_edges(nf.skin);
  const long faces = static_cast<long>(nf.skin.size());
  std::vector<Eigen::Vector3d> apex_at(nf.skin.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (long f = 0; f < faces; ++f) {
    const auto& v = nf.skin[f].nodes;
    if (nf.skin[f].count == 4)
      apex_at[f] = pyramid_apex({mesh.node(v[0]), mesh.node(v[1]), mesh.node(v[2]), mesh.node(v[3])},
                                slope_caps(nf, mesh, static_cast<std::size_t>(f), face_of_edge));
  }
  std::vector<Triangle> triangles;
  int region = -1;
  for (std::size_t f = 0; f < nf.skin.size(); ++f) {
    const nearfield::SkinFace& face = nf.skin[f];
    const auto& v = face.nodes;
    if (face.count == 3) {
      triangles.push_back({v[0], v[1], v[2]});
      continue;
    }
    const NodeId apex = mesh.add_node(apex_at[f]);
    if (region < 0) region = mesh.region_index("farfield");
    mesh.add_element(ho::Shape::Pyramid, {v[0], v[1], v[2], v[3], apex}, region);
    pyramids.push_back({apex, {v[0], v[1], v[2], v[3]}});
    for (int k = 0; k < 4; ++k) triangles.push_back({v[k], v[(k + 1) % 4], apex});
  }
  return triangles;
}

// The interior points' spacing grows from the boundary's by this ratio per unit of spacing: the
// rate at which TetGen's radius-edge refinement (1.5) grows its tets on the paper's case, where
// the far field then keeps its element count within 3 % (docs/benchmarks.md).
constexpr double kInteriorGrowth = 1.6;
// TetGen's refinement after the interior points: at most this share of the input's points. It
// takes the worst tets first (slivers among the boundary's own points: a wake's flat pyramids), and
// with them its mesh optimisation, which only runs with refinement on; uncapped, each of its points
// next to the kept boundary costs ~300 us, and more as the mesh grows.
constexpr double kRefinementShare = 0.02;

// TetGen 1.5.0 cannot refine a tetrahedron of zero volume (its circumcentre is at infinity: an
// assertion in locate() aborts), and its constrained Delaunay mesh has such tets where input
// points are exactly coplanar and cocircular. Skin quads that are copies of each other by a
// translation (a wake block's strips where its layer ratio is 1) carry apexes at equal heights,
// which line up with the quads' own edges exactly so (sweep seed 77 run 4: the wake's outflow end
// beside the sharp edge's tip). Varying each apex's height by up to kApexVariation, in a fixed
// pattern along the skin, breaks the tie; an apex whose pyramid would not stay valid keeps its place.
constexpr double kApexVariation = 0.02;

// TetGen's first try meshes the boundary points moved by up to this share of their shortest edge
// (untie_boundary): measured on the paper's case, 1e-10 to 1e-8 all halve its Delaunay phase (1e-8
// a little more), 1e-6 and more slow its boundary recovery; 1e-8 of an edge is far above the
// predicates' round-off (~1e-15 relative) and far below any sound tet's 6 V / L^3 (~1e-7).
constexpr double kUntie = 1e-8;

// Node `id`'s index among TetGen's input points (plc_index: [nodes], -1 for a node not in it).
int plc_point(const std::vector<int>& plc_index, NodeId id) {
  const int index = plc_index.at(id);
  if (index < 0) throw std::logic_error("far field: node " + std::to_string(id) + " is not on TetGen's boundary");
  return index;
}

void vary_apex_heights(const std::vector<SkinPyramid>& pyramids, const std::vector<int>& plc_index,
                       mesh::Mesh& mesh, TetgenInput& input) {
  constexpr int kPattern = 5;  // factors 1 - v, 1 - v/2, 1, 1 + v/2, 1 + v
  for (std::size_t k = 0; k < pyramids.size(); ++k) {
    const SkinPyramid& p = pyramids[k];
    Eigen::MatrixX3d nodes(5, 3);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      nodes.row(i) = mesh.node(p.base[i]).transpose();
      centre += 0.25 * mesh.node(p.base[i]);
    }
    const double factor = 1.0 + kApexVariation * (static_cast<int>(k % kPattern) - kPattern / 2) / (kPattern / 2);
    const Eigen::Vector3d apex = centre + factor * (mesh.node(p.apex) - centre);
    nodes.row(4) = apex.transpose();
    if (!ho::certify_jacobian(ho::Shape::Pyramid, 1, ho::NodeSet::Equispaced, nodes).valid) continue;
    mesh.place_node(p.apex, apex);
    input.points[plc_point(plc_index, p.apex)] = apex;
  }
}

// TetGen on the input (first on its untied boundary, kUntie); when it fails (a zero-volume tet
// among exactly degenerate points, which it aborts on, or answers with when round-off makes it not
// quite flat: run_tetgen refuses that answer), again with its refinement uncapped (its capped
// refinement and mesh optimisation can leave a flat tet that further refinement takes away: the
// NekMesh wing's coarse case), then with the apexes' heights varied; the first failure is the one
// reported when all fail.
// `beside` runs beside the first try only (the last moves apexes of the mesh it reads).
TetgenOutput run_tetgen_with_retries(TetgenInput& input, const std::vector<SkinPyramid>& pyramids,
                                     const std::vector<int>& plc_index, mesh::Mesh& mesh,
                                     const BesideChild& beside) {
  std::optional<FarFieldError> first;
  input.untie = kUntie;
  try {
    return run_tetgen(input, /*quiet=*/true, beside);
  } catch (const FarFieldError& e) {
    first = e;
  }
  input.untie = 0.0;  // the tries below as before untying: on the true points only
  input.max_added_points = -1;
  try {
    return run_tetgen(input, /*quiet=*/!pyramids.empty());
  } catch (const FarFieldError&) {
    if (pyramids.empty()) throw *first;
  }
  const std::vector<Eigen::Vector3d> points = input.points;
  vary_apex_heights(pyramids, plc_index, mesh, input);
  try {
    return run_tetgen(input);
  } catch (const FarFieldError&) {
    for (const SkinPyramid& p : pyramids) mesh.place_node(p.apex, points[plc_point(plc_index, p.apex)]);
    throw *first;
  }
}

// TetGen's tets into the mesh (region "farfield"), `plc_node` the mesh's node of each boundary
// point, given to it; the interior points and TetGen's own become nodes when a tet uses them (an
// interior point the ray test put inside by mistake stays in TetGen's list, carved away with the
// outside).
void add_tetrahedra(const TetgenOutput& output, std::vector<NodeId> plc_node, mesh::Mesh& mesh) {
  std::vector<char> used(output.points.size(), 0);
  for (const auto& t : output.tets)
    for (int v : t) used[v] = 1;
  const std::size_t boundary_points = plc_node.size();
  plc_node.resize(output.points.size(), mesh::kNoNode);
  for (std::size_t i = boundary_points; i < output.points.size(); ++i)
    if (used[i]) plc_node[i] = mesh.add_node(output.points[i]);
  mesh.reserve(ho::Shape::Tetrahedron, mesh.elements().size() + output.tets.size());  // all it will hold
  // Sized ahead (a lookup that grows rehashes every key it holds): a Delaunay mesh has about 1.2-1.4
  // edges and 2.1-2.2 faces per tetrahedron (the paper's case: ~1.4 and ~2.16).
  const std::size_t tets = output.tets.size();
  mesh.reserve_lookups(mesh.edges().size() + 3 * tets / 2, mesh.faces().size() + 9 * tets / 4);
  std::vector<NodeId> corners;
  corners.reserve(4 * tets);
  for (const auto& t : output.tets)
    for (int v : t) corners.push_back(plc_node[v]);
  mesh.add_linear_elements(ho::Shape::Tetrahedron, corners, mesh.region_index("farfield"));
}

}  // namespace

FarField build_far_field(const cad::Model& model, nearfield::NearField near, const FarFieldParams& params,
                         const std::vector<int>& box_surfaces, int wall_surface, double wall_layer_thickness,
                         const ProgressCallback& progress, const BesideTetgen& beside) {
  // Progress at the start of each sub-step, at rough shares of the time: TetGen, one call in a
  // child process that cannot report, takes most of it.
  const auto report = [&](double fraction, const char* step) {
    if (progress) progress(fraction, step);
  };
  const nearfield::NearField& nf = near;
  check_params(model, nf, params, box_surfaces, wall_surface);
  if (!(wall_layer_thickness >= 0) || !std::isfinite(wall_layer_thickness))
    throw FarFieldError("far field: the wall layer's thickness must be >= 0 (0: no wall layer), got " +
                        std::to_string(wall_layer_thickness));
  mesh::Mesh& mesh = near.mesh;
  FarFieldStats stats;
  report(0.0, "box and wall");

  // Box sizes are uniform: the box is planar and far from the body, so no curvature sources; a
  // curved wall's curves (a fuselage's ends, its seam) follow its curvature.
  surface::SizeParams size_params;
  size_params.max_size = params.box_size;
  size_params.min_size = std::min(size_params.min_size, params.box_size);
  const bool curved_wall = !model.surface(wall_surface).is_planar();
  const double wall_segments =
      curved_wall ? curved_wall_segments(model, wall_surface, near, mesh, wall_layer_thickness) : 0.0;
  size_params.curvature_segments = wall_segments;
  size_params.gradation = params.growth;
  size_params.le_curves.clear();
  size_params.te_curves.clear();
  const surface::SizeField size(model, size_params);
  const surface::CurveMeshes curves = surface::discretise_all_curves(model, size);
  CurveNodes curve_nodes(model, curves, mesh);

  // An H-type's wake run to the far field's downstream face: that face is meshed round it, after
  // the wall layer has lifted its outline.
  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());
  const int outlet = nf.outlet.empty() ? -1 : outlet_surface(model, box_surfaces, nf, tolerance);
  std::vector<Triangle> box = mesh_box(model, box_surfaces, outlet, curves, size, curve_nodes, mesh);
  std::vector<NodeId> outlet_outline;
  if (outlet >= 0) outlet_outline = outer_loop_nodes(model, outlet, curve_nodes);
  const std::vector<Triangle> wall = model.surface(wall_surface).is_planar()
                                         ? mesh_planar_wall(model, wall_surface, nf, params, curve_nodes, mesh)
                                         : mesh_curved_wall(model, wall_surface, nf, params, wall_segments, curves,
                                                            curve_nodes, mesh);
  std::vector<SkinPyramid> pyramids;
  const std::vector<Triangle> skin = cap_skin(nf, mesh, pyramids);
  stats.pyramids = static_cast<int>(pyramids.size());
  // With a wall layer, its tops stand between the wall and the tetrahedra.
  std::vector<Triangle> wall_side = wall;
  std::vector<nearfield::LayerStack> stacks = nf.stacks;
  if (wall_layer_thickness > 0) {
    report(0.1, "wall layer");
    const WallLayer layer =
        build_wall_layer(model, wall_surface, box_surfaces, wall_layer_thickness, wall, nf, box, outlet_outline, mesh);
    wall_side = layer.tops;
    stats.wall_layer_prisms = static_cast<int>(layer.stacks.size());
    stacks.insert(stacks.end(), layer.stacks.begin(), layer.stacks.end());
    for (NodeId& v : outlet_outline)
      if (const auto it = layer.top_of.find(v); it != layer.top_of.end()) v = it->second;
  }
  if (outlet >= 0) {
    const std::vector<Triangle> around_wake = mesh_outlet(model, outlet, outlet_outline, nf, params, mesh);
    box.insert(box.end(), around_wake.begin(), around_wake.end());
  }

  // The closed boundary of the tetrahedral region, numbered densely for TetGen.
  TetgenInput input;
  input.radius_edge_ratio = params.radius_edge_ratio;
  input.max_volume = params.max_volume;
  std::vector<int> plc_index(mesh.num_nodes(), -1);  // [nodes] its index in TetGen's input, -1: none
  std::vector<NodeId> plc_node;
  const std::pair<const std::vector<Triangle>*, const char*> groups[] = {
      {&skin, "the near field's outer skin"}, {&wall_side, "the wall"}, {&box, "the far field's outer boundary"}};
  for (const auto& [group, name] : groups) {
    for (const Triangle& t : *group) {
      std::array<int, 3> local;
      for (int k = 0; k < 3; ++k) {
        int& index = plc_index.at(t[k]);
        if (index < 0) {
          index = static_cast<int>(plc_node.size());
          plc_node.push_back(t[k]);
          input.points.push_back(mesh.node(t[k]));
        }
        local[k] = index;
      }
      input.triangles.push_back(local);
    }
    input.parts.emplace_back(input.triangles.size(), name);
  }
  report(0.12, "interior points");
  const std::vector<Eigen::Vector3d> inside = interior_points(input.points, input.triangles, {kInteriorGrowth, params.box_size});
  input.points.insert(input.points.end(), inside.begin(), inside.end());
  input.max_added_points = static_cast<int>(std::ceil(kRefinementShare * static_cast<double>(input.points.size())));
  stats.interior_points = static_cast<int>(inside.size());
  report(0.15, "TetGen");
  BesideChild beside_child;
  if (beside)
    beside_child = [&](const std::atomic<bool>& stop) {
      beside(static_cast<const mesh::Mesh&>(mesh), static_cast<const std::vector<nearfield::LayerStack>&>(stacks), stop);
    };
  const TetgenOutput output = run_tetgen_with_retries(input, pyramids, plc_index, mesh, beside_child);
  report(0.9, "elements");
  stats.seconds_tetgen = output.seconds;
  stats.tetgen_untied = output.untied;
  stats.added_points = static_cast<int>(output.points.size() - input.points.size());
  add_tetrahedra(output, plc_node, mesh);
  stats.tets = static_cast<int>(output.tets.size());

  for (const Triangle& t : wall) mesh.add_boundary_face("wall", ho::Shape::Triangle, {t[0], t[1], t[2]});
  for (const Triangle& t : box) mesh.add_boundary_face("farfield", ho::Shape::Triangle, {t[0], t[1], t[2]});
  stats.wall_triangles = static_cast<int>(wall.size());
  stats.box_triangles = static_cast<int>(box.size());
  if (params.symmetry != "none") stats.symmetry_faces = move_symmetry_faces(mesh, params.symmetry, tolerance);
  report(1.0, "");
  return {std::move(mesh), stats, std::move(stacks)};
}

}  // namespace semimesh::farfield
