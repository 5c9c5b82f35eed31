// Curving a linear mesh onto its CAD model, bottom-up (paper, section "High-order mesh generation").
// With placement = Springs (placement = Parameter skips the optimisation, see below):
//  1. edges: nodes of an edge on a CAD curve are placed by arc length at the node set's fractions
//     (the exact optimum of the spring chain on a curve); nodes of an edge inside a CAD surface start
//     at the node set's fractions of the straight line in the surface's (u, v) and are then moved by
//     the spring optimisation below, constrained to the surface, so they lie near the geodesic;
//  2. faces: interior nodes of a boundary face on a CAD surface start from the harmonic extension
//     of the face's boundary (u, v) (then S(u, v)), and are optimised by the spring network of the
//     face's own node lattice with the edge nodes fixed; other faces (the skin, internal faces) take
//     the extension of their boundary nodes in 3D (harmonic; transfinite for a quadrilateral), so a
//     face with straight edges stays flat;
//  3. volumes: interior nodes are the extension of the curved boundary nodes (harmonic; transfinite
//     for a prism, so a thin layer prism carries its curved base's bulge linearly across to its top:
//     curving/harmonic_extension.hpp), exact for the element's linear map and smooth otherwise.
// Spring optimisation: every free node is pulled by springs to its lattice neighbours with weights
// that make the node set's own reference positions the equilibrium (force balance exact for an
// affine face); the squared force imbalance is minimised by damped Gauss-Newton in (u, v). It stops
// when no node moves more than tolerance x (edge/face length); when it does not converge within
// spring_iterations, or leaves the trimmed face, the projected start positions are kept (a fallback).
// Node placement (CurvingParams::placement):
//  - Parameter (default): no optimisation; the node set's fractions of the curve parameter interval,
//    of the straight segment in (u, v), and the harmonic extension of the face's boundary (u, v).
//    This is the interpolant of the CAD map composed with a smooth parameter map, so the geometric
//    error falls like h^(P+1) (measured rates 3.0, 4.0, 5.0 at P = 2, 3, 4 on the NACA upper surface).
//  - Springs: arc length on curves and the spring optimisation described above. It spaces nodes
//    evenly in 3D (useful on a badly parametrised CAD face) but its equilibrium is not the smooth
//    interpolant: next to the leading edge, on faces of aspect ratio ~1000, the geometric error only
//    falls like h^3 at P = 3 and 4, and arc-length placement on a curve alone already costs that
//    (measured; see tests/highorder/ho_mesh/test_curve_mesh.cpp).
//  Either way, next to a pole with a tangent plane (a rounded nose, a revolved tip: within
//  pole_reach = 3 element sides of it, a face only when all its sides are) the parameters are polar
//  and no smooth chart: there the nodes are the closest points of the surface to the straight-sided
//  element's nodes (measured rates 4.0, 4.0, 6.0 at P = 2, 3, 4 on an ellipsoid's pole, 2.0 in the
//  polar parameters; test_curve_periodic.cpp; the reach: bench/ho_mesh/bench_pole_reach.cpp).
//  Either way too, on a surface or curve whose parametric speed jumps (Bezier patches joined at
//  knots of full multiplicity, as OpenVSP exports wings: smooth geometry, kinked parameters) the
//  parameters are first mapped piecewise linearly so that the speed is continuous at each kink,
//  and the nodes placed at fractions of those (curving/kinked_parameters.hpp;
//  test_curve_kinked_parameters.cpp). CurvingStats counts the kinked surfaces and curves.
// Which CAD entity an edge or face lies on comes from the CAD attachments of its vertices (see
// cad_classification in the sources); only edges and faces of boundary faces are curved.
#pragma once

#include "semimesh/params/table.hpp"
#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <atomic>
#include <cstdint>
#include <vector>

namespace semimesh::ho {

enum class NodePlacement { Parameter, Springs };

/// The keys a user sets (ranges, meanings): curving_keys(), the config's [highorder] section.
struct CurvingParams {
  int order = 4;                       ///< polynomial order P of the result
  NodeSet node_set = NodeSet::GLL;     ///< node set of the result
  int spring_iterations = 50;          ///< Gauss-Newton iterations per edge/face before falling back
  double tolerance = 1e-10;            ///< relative move below which the optimisation has converged
  NodePlacement placement = NodePlacement::Parameter;  ///< see the top of this file
  /// Edges and faces with a vertex within pole_reach times their longest side of a pole (with a
  /// tangent plane) are placed by projection (see the top of this file); beyond it, by parameters.
  double pole_reach = 3.0;
};

/// One row per user key of CurvingParams (semimesh/params/table.hpp).
const params::Table<CurvingParams>& curving_keys();

struct CurvingStats {
  int edges_on_curves = 0;
  int edges_on_surfaces = 0;
  int faces_on_surfaces = 0;
  int optimisation_fallbacks = 0;       ///< edges + faces that kept their projected start positions (Springs)
  int kinked_surfaces = 0;  ///< surfaces whose parametric speed jumps: nodes on them placed by projection
  int kinked_curves = 0;    ///< curves whose parametric speed jumps: nodes on them placed by arc length
  double max_projection_distance = 0.0; ///< largest distance from a straight-sided node to its CAD position
};

/// The curving of a mesh made before the rest of it (curve_ahead: e.g. the near field's elements,
/// curved while TetGen's process makes the far field), for curve_mesh to take the nodes it placed.
struct CurvedAhead {
  /// How an edge or face was placed (curve_mesh's statistics of it).
  struct Placed {
    std::int8_t place = 0;  ///< on no CAD entity (0), a curve (1) or a surface (2)
    bool fallback = false;  ///< the spring optimisation kept its start positions
    double moved = 0.0;     ///< largest distance from a straight-sided position to the placed one
  };
  mesh::Mesh curved;                 ///< curve_mesh(so_far, ...); no elements when not curved
  std::size_t linear_nodes = 0;      ///< so_far's nodes: curved's first nodes, the same
  std::vector<Placed> edges, faces;  ///< [so_far's edges], [so_far's faces]
  std::vector<char> edge_on_boundary, face_on_boundary;  ///< [edges], [faces]: on a boundary face of so_far
  bool empty() const { return curved.elements().empty(); }
};

/// A new mesh of order params.order from the order-1 mesh `linear` whose boundary vertices carry CAD
/// attachments. Node ids 0..linear.num_nodes()-1 are the linear mesh's vertices (same attachments);
/// elements and boundary faces keep their indices and groups. New nodes on CAD carry their curve or
/// surface attachment. Throws std::invalid_argument when `linear` is not order 1 or a parameter is
/// out of range, and cad::CadError when an attachment names an entity the model does not have.
/// `progress` receives the fraction of edges, faces and volumes placed (steps "edges", "faces",
/// "volumes"), from one thread, throttled; it does not change the result.
/// `ahead` (optional; the same model and params): an edge, face or element of `linear` that is the
/// one of the same index in the mesh curved ahead (the same vertices, edges, faces and orientations,
/// and for an edge or face the same boundary flag; its edges and faces taken too) takes the nodes
/// placed there instead of placing them again, when the first ahead->linear_nodes nodes of `linear`
/// are the ahead mesh's (the same bits, the same CAD attachments; else nothing is taken): the same
/// mesh and statistics, placed by the same code on the same inputs. Its `taken` (optional) receives
/// the number of edges, faces and elements taken.
mesh::Mesh curve_mesh(const mesh::Mesh& linear, const cad::Model& model, const CurvingParams& params,
                      CurvingStats* stats = nullptr, const ProgressCallback& progress = {},
                      const CurvedAhead* ahead = nullptr, std::size_t* taken = nullptr);

/// curve_mesh(so_far, model, params) kept for a later curve_mesh of a mesh that begins with
/// so_far's nodes and entities (CurvedAhead), computed on the calling thread alone (one OpenMP
/// thread, its setting restored after: Eigen's products then run on one thread, as inside curve_mesh's
/// parallel loops, the same bits). Empty when the curving throws (the later curving says why) or
/// `stop` is set before it ends (checked between edges, faces and elements): work that only speeds
/// up a later stage, beside another (TetGen's process), that returns soon when told to.
CurvedAhead curve_ahead(const mesh::Mesh& so_far, const cad::Model& model, const CurvingParams& params,
                        const std::atomic<bool>& stop);

}  // namespace semimesh::ho
