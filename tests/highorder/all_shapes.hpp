// Every element shape and node set, for tests that run a check over all of them.
#pragma once

#include "semimesh/ho/element_type.hpp"

namespace semimesh::ho::testing {

inline constexpr Shape kAllShapes[] = {Shape::Segment, Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron,
                                       Shape::Pyramid,  Shape::Prism,    Shape::Hexahedron};
inline constexpr NodeSet kSets[] = {NodeSet::Equispaced, NodeSet::GLL};

}  // namespace semimesh::ho::testing
