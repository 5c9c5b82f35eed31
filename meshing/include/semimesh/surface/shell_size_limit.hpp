// Surface sizes a straight-sided shell can stand on a curved body.
//
// The near-field prisms have a body face curved onto the CAD and a straight outer face at the
// thickness delta along the node normals. Across a body edge of length h on a convex arc, the
// outer face's chord between the two offset points passes at the gap
//     g(h) = ((A + delta n_A + B + delta n_B) / 2 - M) . n_M
// outside the arc's midpoint M (A, B its ends). Along each wall-normal line the prism's map is
// linear between the curved and the straight face, so det J keeps its sign while that gap stays
// positive along the edge (exact for the 2D section of the prism); a coarse edge on a small radius
// R makes g <= 0 and the prism folds (on a circle: (R + delta) cos(h / 2R) <= R). We keep
// g >= min_gap_fraction * delta: the largest such h is the edge length the shell allows there.
// The arc is the real one (marched on the surface along its direction of largest curvature and
// stopping at the surface's boundary, where the mesh has nodes), so a curvature peak on a boundary
// curve, such as a wing's leading edge, costs only what the mesh really sees.
// The 3D prism folds earlier than this 2D model says (measured on NACA 0006 and 2412 noses at
// orders 3 to 5, see shell_size_limit.cpp): shell_size_sources turns the edge length into a
// target size (the mesher's longest edges are about 1.5 x the target) and, where the body turns
// fast, also caps it at max(0.75 delta, radius). Empirical, and conservative on the cases measured.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/progress.hpp"
#include "semimesh/surface/size_field.hpp"

#include <vector>

namespace semimesh::surface {

struct ShellSizing {
  double thickness = 0.0;           ///< shell thickness delta (model unit), > 0
  std::vector<int> body_surfaces;   ///< surfaces the shell stands on
  double min_gap_fraction = 0.5;    ///< the outer face stays this fraction of delta off the body
  int samples = 48;                 ///< samples per surface direction
};

/// One place where the shell limits the surface size.
struct ShellSizeLimit {
  Vec3 point = Vec3::Zero();
  int surface = -1;
  double radius = 0.0;    ///< radius of curvature there (1 / largest principal curvature)
  double size = 0.0;      ///< largest body edge length the shell allows there
  /// Smallest thickness that allows edges of `probe_size` there (infinity: none does).
  double thickness_for_probe = 0.0;
};

/// The places on the body where the shell allows less than `max_size`, with the thickness each needs
/// for edges of `probe_size` (e.g. sizing.min_size). Only convex curvature limits the size.
/// `progress`: the fraction of sample rows done (step "shell limits"), one call at a time from
/// whichever thread ends a row.
std::vector<ShellSizeLimit> shell_size_limits(const cad::Model& model, const ShellSizing& shell, double max_size,
                                              double probe_size, const ProgressCallback& progress = {});

/// Throws SurfaceMeshError naming the worst place, its radius, the size it needs and the values that
/// would work (min_size, or a thickness) when some limit is below `min_size`; otherwise returns the
/// limits as point sources for SizeParams::point_sources.
/// `progress` as shell_size_limits'.
std::vector<PointSource> shell_size_sources(const cad::Model& model, const ShellSizing& shell, const SizeParams& sizing,
                                            const ProgressCallback& progress = {});

/// The largest sizing.min_size that shell_size_sources accepts with this shell and max_size: the
/// smallest size it asks for anywhere on the body (infinity where the shell limits nothing).
double smallest_shell_size(const cad::Model& model, const ShellSizing& shell, double max_size,
                           const ProgressCallback& progress = {});

}  // namespace semimesh::surface
