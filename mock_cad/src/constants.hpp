// Constants the analytic model's entities share.
#pragma once

namespace semimesh::mock_cad::detail {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
/// A crease parameter outside every parameter range: the surface or curve is smooth everywhere.
inline constexpr double kNoCrease = -1.0;

}  // namespace semimesh::mock_cad::detail
