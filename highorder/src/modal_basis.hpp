// Orthonormal modal bases of the element spaces (internal): the Vandermonde side of LagrangeBasis.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

#include <array>

namespace semimesh::ho::detail {

/// Number of modal functions = num_nodes(shape, order).
int modal_size(Shape shape, int order);

/// Values (npoints, modal_size) of the modal functions at reference points (npoints, 3), and, when
/// `gradients` is not null, their derivatives d/dxi_k (each (npoints, modal_size)).
Eigen::MatrixXd modal_values(Shape shape, int order, const Eigen::MatrixX3d& points,
                             std::array<Eigen::MatrixXd, 3>* gradients = nullptr);

}  // namespace semimesh::ho::detail
