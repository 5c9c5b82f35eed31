// The registry of every CAD backend the project knows, built into this binary or not.
#pragma once

#include "semimesh/cad/registry.hpp"

namespace semimesh::backends {

/// "naca" (analytic wing generator), "occ" (STEP/IGES/BREP/FCStd files, or a B-spline NACA wing
/// when no file is given) and "vendor" (proprietary CAD API). Those not built are listed as
/// unavailable with the reason, so loading them fails with a message instead of a crash.
cad::Registry default_registry();

}  // namespace semimesh::backends
