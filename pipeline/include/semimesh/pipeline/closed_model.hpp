// A CAD model the mesher can fill is closed: every curve bounds two faces (a seam one face twice,
// a pole one face once). A curve that bounds one face only is free: the faces were not sewn at the
// tolerance (a gap wider than it), or a face is missing.
#pragma once

#include "semimesh/cad/model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace semimesh::pipeline {

/// The free curves, ascending.
std::vector<int> free_curves(const cad::Model& model);

/// "curve 12 ('edge_12') of surface 5 ('Join.13') from (x, y, z) to (x, y, z)", the first `shown`
/// of them, then how many more.
std::string free_curves_text(const cad::Model& model, const std::vector<int>& curves, std::size_t shown = 6);

/// Throws ConfigError naming the free curves and the sewing tolerance when the model is not closed.
void require_closed(const cad::Model& model, std::optional<double> sew_tolerance);

}  // namespace semimesh::pipeline
