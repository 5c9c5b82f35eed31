// OCC's coordinates as cadapi's vector (one definition for the curve and surface wrappers).
#pragma once

#include "semimesh/cad/types.hpp"

#include <gp_XYZ.hxx>

namespace semimesh::occ {

inline cad::Vec3 to_vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace semimesh::occ
