// What PyFR's Gmsh importer cannot take, found before the user tries (pyfr/readers/base.py,
// NodalMeshAssembler._check_pyr_parallelogram; see docs/solvers.md): pyramids whose base is not a
// parallelogram to within 1e-10 in each coordinate, and element orders above 4.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace semimesh::pipeline {

/// PyFR's absolute tolerance on a pyramid base's b0 - b1 + b2 - b3, per coordinate.
constexpr double kPyfrParallelogramTolerance = 1e-10;

/// Pyramids of `mesh` whose base vertices b0 b1 b2 b3 (in cyclic order) miss b0 + b2 = b1 + b3 by
/// more than PyFR's absolute 1e-10 in some coordinate.
std::size_t pyramids_pyfr_refuses(const mesh::Mesh& mesh);

/// One warning per reason PyFR would refuse `mesh` written as MSH (none when it would import it).
std::vector<std::string> pyfr_refusals(const mesh::Mesh& mesh);

}  // namespace semimesh::pipeline
