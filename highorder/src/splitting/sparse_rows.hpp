// Basis values at the split pieces' nodes, kept by their entries that are not zero.
//
// The pieces' nodes keep the coarse element's reference coordinates across the split directions,
// where each coarse basis function is 1 or 0 (to round-off): a row of the values has P + 1 (one
// split direction) or (P + 1)^2 (two) entries of up to (P + 1)^3 that are not 0. Summing only those
// takes 1/15 to 1/100 of the operations of the dense product, which was the split's largest cost.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace semimesh::ho::detail {

struct SparseRows {
  std::vector<int> first;     ///< [rows + 1] where each row's entries start in column / value
  std::vector<int> column;    ///< [entries]
  std::vector<double> value;  ///< [entries]
};

/// The entries of `values` ((rows, cols), basis values of magnitude ~1) larger than `zero` in
/// magnitude: those below are round-off of a 0.
SparseRows sparse_rows(const Eigen::MatrixXd& values, double zero = 1e-12);

/// values * X for the values `rows` keeps: (rows, 3), X (cols, 3).
Eigen::MatrixX3d multiply(const SparseRows& rows, const Eigen::MatrixX3d& X);

}  // namespace semimesh::ho::detail
