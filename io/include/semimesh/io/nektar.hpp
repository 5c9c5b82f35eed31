// Nektar++ XML geometry (<NEKTAR><GEOMETRY DIM="3" SPACE="3">): VERTEX, EDGE, FACE (T/Q),
// ELEMENT (A tet, P pyramid, R prism, H hex), CURVED (E and F, TYPE="PolyEvenlySpaced"),
// COMPOSITE, DOMAIN. Conventions (Nektar++ user guide "XML mesh format", SpatialDomains
// TetGeom/PyrGeom/PrismGeom/HexGeom, NekMesh Face::GetCurvedNodes):
//  - vertex ids: element vertices renumbered from 0; edge/face ids = mesh edge/face indices.
//  - E: "v0 v1" = the edge's own direction; curved E points run v0 -> v1, NUMPOINTS = P+1.
//  - T: edges (f0f1, f1f2, f2f0) of the face's stored vertices f0 f1 f2; Q: (f0f1, f1f2, f2f3, f3f0).
//  - curved F, triangle (P >= 3): NUMPOINTS = (P+1)(P+2)/2 in Nektar's NodalTriEvenlySpaced
//    order: f0 f1 f2, the points inside f0->f1, f1->f2, f2->f0, then the interior row by row
//    (along f0->f1 fastest, rows moving towards f2), the order NekMesh writes since Nektar++ MR !576.
//    Quadrilateral (P >= 2): NUMPOINTS = (P+1)^2 tensor order, f0->f1 fastest, rows towards f3.
//  - element faces in Nektar's local face order; a prism's Nektar vertices (0..5) are Gmsh's
//    (0, 2, 5, 3, 1, 4) so that its quad face 0 is (0 1 2 3), triangles (0 1 4), (3 2 5), and the
//    element stays right-handed. Tets, pyramids, hexes keep Gmsh's vertex numbering.
//  - composites: C[0..] one per element shape, then one per boundary group (F[...], preceded by a comment
//    naming the group);
//    DOMAIN lists the element composites.
// No Nektar++ is available here: tests/io/verify_nektar.py checks the structure and that every
// curved point lies on the element map; Nektar++'s own collapsed-coordinate orientation rules for
// tets/prisms (NekMesh reorders such elements) are not applied.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>

namespace semimesh::io {

/// Writes atomically; GLL meshes are resampled to equispaced points.
void write_nektar_xml(const mesh::Mesh& mesh, const std::string& path);

}  // namespace semimesh::io
