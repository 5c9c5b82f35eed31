// Finds a tetrahedron of zero volume to round-off in TetGen's answer: the far field treats one as
// TetGen's failure (run once more with the apexes' heights varied, else refused), never hands it on.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace semimesh::farfield {

struct FlatTet {
  std::size_t tet = 0;        ///< its index
  double relative = 0.0;      ///< |6 volume| / (longest edge)^3
};

/// The flattest tetrahedron whose six times volume is at most `relative_tolerance` times its
/// longest edge cubed (the whole tet round-off from flat), if any.
std::optional<FlatTet> find_flat_tet(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 4>>& tets, double relative_tolerance);

}  // namespace semimesh::farfield
