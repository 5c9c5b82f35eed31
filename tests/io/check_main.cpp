// Test helper: `io_check MESH.msh [--json]` runs semimesh::io::run_check (what `semimesh check`
// does) so the Python tests can compare its verdicts with gmsh's.
#include "semimesh/io/check.hpp"

#include <iostream>

int main(int argc, char** argv) {
  return semimesh::io::run_check(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
