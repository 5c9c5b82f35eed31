// Nektar++ XML geometry (<NEKTAR><GEOMETRY DIM="3" SPACE="3">) that passes Nektar++'s load-time
// checks (see io/src/nektar_numbering.hpp for the numbering rules and why), plus an EXPANSIONS
// section so NekMesh / FieldConvert open the file alone.
//  - VERTEX: element vertices, ids ranked so that the rules can hold; EDGE "v0 v1" in the edge's own
//    direction; FACE T/Q as edge lists (a triangle rotated so its highest vertex id is third);
//    ELEMENT A/P/R/H as face lists in Nektar's local face order (TetGeom/PyrGeom/PrismGeom/HexGeom).
//  - CURVED (P >= 2), only for edges and faces whose nodes are off the straight-sided (affine /
//    bilinear) map, as NekMesh writes: an edge, P+1 PolyEvenlySpaced points from its first vertex
//    to its second;
//    triangles (P >= 3) NodalTriEvenlySpaced, (P+1)(P+2)/2 points: the face's vertices, the points
//    inside its edges 0-1, 1-2, 2-0, then the interior row by row (along 0->1 fastest, rows towards
//    vertex 2), the order NekMesh writes since Nektar++ MR !576; quadrilaterals PolyEvenlySpaced,
//    (P+1)^2 points in tensor order, 0->1 fastest, rows towards vertex 3. Element-interior nodes
//    are not part of the format.
//  - COMPOSITE: one per (region, element letter), NAME = the region; then one per boundary group,
//    F[...], NAME = the group. DOMAIN lists the element composites; EXPANSIONS gives each element
//    composite NUMMODES = P+1, TYPE MODIFIED, field u.
// Compressed: VERTEX, EDGE, FACE, ELEMENT and CURVED hold Nektar++'s binary records (64-bit
// integers and doubles, little endian; SpatialDomains/MeshEntities.hpp), one zlib stream per block,
// base64 encoded, COMPRESSED="B64Z-LittleEndian" BITSIZE="64" (MeshGraphIOXmlCompressed.cpp).
#pragma once

#include "semimesh/io/equispaced.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <string>

namespace semimesh::io {

enum class NektarEncoding { Compressed, Plain };

/// Writes atomically; GLL meshes are resampled to equispaced points. Throws std::runtime_error
/// naming the element if Nektar++'s rules cannot be met (see nektar_numbering.hpp), or on I/O errors.
void write_nektar_xml(const mesh::Mesh& mesh, const std::string& path,
                      NektarEncoding encoding = NektarEncoding::Compressed);
/// The same with the equispaced node positions given (computed once for several formats).
void write_nektar_xml(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
                      NektarEncoding encoding = NektarEncoding::Compressed);

}  // namespace semimesh::io
