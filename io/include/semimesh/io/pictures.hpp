// Pictures of a mesh written as SVG, with no GUI and no dependency: a cut by a plane normal to a
// coordinate axis (every element it crosses, filled by region, curved edges drawn curved), the
// surface mesh of a boundary group seen along an axis, and a histogram of the scaled Jacobian.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace semimesh::io {

/// A rectangle of the picture plane (its two axes in increasing order, e.g. x, y for a cut normal
/// to z): {min0, min1, max0, max1}. An empty window (min >= max) shows everything drawn.
using Window = std::array<double, 4>;

struct CutPicture {
  std::string svg;
  std::size_t elements_cut = 0;  ///< elements drawn: one closed <path class="element"> each
};

/// The cut of `mesh` by the plane x[axis] = station (axis 0, 1, 2). Each crossed element's faces
/// are sampled at 2P intervals per edge through the element's own map, so curved elements show
/// curved. Elements are filled by region; `window` crops the view (elements outside it are left out).
CutPicture svg_cut(const mesh::Mesh& mesh, int axis, double station, const Window& window, const std::string& title);

/// The boundary faces of `group` projected along `axis` (edges sampled at the mesh's order).
std::string svg_surface(const mesh::Mesh& mesh, const std::string& group, int axis, const std::string& title);

/// Histogram of per-element scaled Jacobians, one bar series per element type, bins of width 0.05
/// on [0, 1] and one bin for the invalid (< 0 or unproven) ones, which is counted in the title.
std::string svg_histogram(const std::map<std::string, std::vector<double>>& scaled_jacobians_by_type,
                          const std::string& title);

}  // namespace semimesh::io
