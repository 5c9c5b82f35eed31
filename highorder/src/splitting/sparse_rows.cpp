#include "sparse_rows.hpp"

#include <cmath>

namespace semimesh::ho::detail {

SparseRows sparse_rows(const Eigen::MatrixXd& values, double zero) {
  SparseRows out;
  out.first.reserve(values.rows() + 1);
  out.first.push_back(0);
  for (Eigen::Index r = 0; r < values.rows(); ++r) {
    for (Eigen::Index c = 0; c < values.cols(); ++c)
      if (std::abs(values(r, c)) > zero) {
        out.column.push_back(static_cast<int>(c));
        out.value.push_back(values(r, c));
      }
    out.first.push_back(static_cast<int>(out.column.size()));
  }
  return out;
}

Eigen::MatrixX3d multiply(const SparseRows& rows, const Eigen::MatrixX3d& X) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.first.size()) - 1;
  Eigen::MatrixX3d out(n, 3);
  for (Eigen::Index r = 0; r < n; ++r) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int k = rows.first[r]; k < rows.first[r + 1]; ++k) sum += rows.value[k] * X.row(rows.column[k]);
    out.row(r) = sum;
  }
  return out;
}

}  // namespace semimesh::ho::detail
