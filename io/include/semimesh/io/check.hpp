// `semimesh check MESH.msh [--json]`: element counts by type and order, invalid elements, scaled
// Jacobians, as a library function the CLI calls.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace semimesh::io {

/// args: the mesh path and optionally "--json" (a leading "check" is ignored).
/// Every volume element is certified with ho::certify_jacobian (Bezier bounds of det J).
/// Prints a summary (or a JSON object with keys "file", "elements" {type: {order: count}},
/// "invalid" [{"index", "type", "centroid"}], "min_scaled_jacobian", "median_scaled_jacobian")
/// to `out`. "index" is the 0-based position among the volume elements in file order.
/// Returns 0 if every element is valid, 2 if any is invalid, 1 if the arguments are wrong or the
/// file cannot be read (the message, with file name and line number, goes to `err`).
int run_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace semimesh::io
