// Volume of a mesh three ways, to catch elements that overlap, leave gaps or are inverted:
//  - element volume: sum over elements of the integral of det J (Gauss quadrature);
//  - boundary volume: (1/3) of the flux of x through the boundary faces (divergence theorem),
//    each face oriented outward through the element it belongs to;
//  - expected volume: the far-field box minus the body, both from the surface meshes the volume
//    mesh was built on (divergence theorem on the triangulated surfaces), or the box from the
//    mesh's own far-field faces when they are curved.
#pragma once

#include "semimesh/mesh/mesh.hpp"
#include "semimesh/surface/surface_mesh.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace semimesh::checks {

struct MeshVolume {
  double element_volume = 0.0;              ///< sum of the integrals of det J
  double boundary_volume = 0.0;             ///< (1/3) flux of x through the boundary faces
  std::size_t boundary_faces_without_element = 0;  ///< skipped (the conformity check names them)
  std::size_t known = 0;                     ///< elements whose integral was given (their certification's)
  double boundary_relative_error() const;   ///< |element - boundary| / |boundary|
};

/// How the element volumes are integrated. Exact: an affine element (ho::affine_jacobian) in closed
/// form, det A times the reference volume; every other one with the fewest Gauss points per shape
/// that integrate the polynomial det J of a tet, prism or hex exactly. Quadrature: that quadrature
/// on every element, affine or not (the reference the closed form is tested against). Generous:
/// every shape with the points of the largest degree any shape's det J reaches, plus two (the
/// reference the exact quadrature is tested against). All three give the same integrals, so agree
/// to rounding on polynomial det J (an element the affine test accepts may deviate from affine by
/// 1e-10 of its size, which moves its det J by at most 3e-6 relative: validity.hpp).
enum class VolumeRule { Exact, Quadrature, Generous };

/// Integrates every element and every boundary face of `mesh` (any order; quadrature exact for the
/// polynomial det J of tets, prisms and hexes; faces always with the generous rule).
/// `known` (optional): by element, the integral of det J its certification of this very mesh found
/// (ho::JacobianBounds::integral: an affine element's det A times the reference volume, a split
/// piece's from its coarse element's det J), NaN where it found none; an element with one takes it
/// instead of integrating its nodes again. Throws std::invalid_argument unless it has one entry per
/// element.
MeshVolume mesh_volume(const mesh::Mesh& mesh, VolumeRule rule = VolumeRule::Exact,
                       const std::vector<double>* known = nullptr);

/// mesh_volume on this thread alone, each sum a plain loop: the reference mesh_volume's threads
/// must match bit for bit (they compute the same terms and add them in the same order).
MeshVolume mesh_volume_one_thread(const mesh::Mesh& mesh, VolumeRule rule = VolumeRule::Exact);

/// Volume of the solid bounded by `faces` (triangles and quads counter-clockwise seen from OUTSIDE
/// the solid) and, where the surface is open, by the plane through `plane_point` with normal
/// `plane_normal` (the wall under a wing). Exact for planar facets; quads are split into two triangles.
double volume_under_surfaces(const std::vector<const surface::SurfaceMesh*>& faces, const Eigen::Vector3d& plane_point,
                             const Eigen::Vector3d& plane_normal);

/// The figures of the volume check.
struct VolumeCheck {
  MeshVolume mesh;
  double box_volume = 0.0;    ///< volume enclosed by the far-field and wall surface meshes
  double body_volume = 0.0;   ///< volume of the body from its surface meshes, closed by the wall plane
  double expected_volume() const { return box_volume - body_volume; }
  double expected_relative_error() const;   ///< |element - expected| / expected
};

/// Runs mesh_volume and computes the box and body volumes from the surface meshes: the fluid
/// normals of the far-field faces point into the box, those of the body out of the solid; the wall
/// surface mesh gives the closing plane (its first node and its mean normal). With `farfield`
/// empty, the box is the one the mesh's own "farfield" boundary faces enclose with that plane,
/// integrated at the mesh's order: a curved far field (a sphere) curved onto its CAD at order > 1
/// encloses more than its triangulation does.
VolumeCheck check_volume(const mesh::Mesh& mesh, const std::vector<const surface::SurfaceMesh*>& body,
                         const std::vector<const surface::SurfaceMesh*>& farfield, const surface::SurfaceMesh& wall,
                         const std::vector<double>* known = nullptr);

/// check_volume for a curved wall (a fuselage): no plane closes the body, so the flux of (x - p) / 3
/// runs through the wall's surface mesh too; box_volume is then the far field's and the wall's part
/// of the fluid's volume, body_volume the body's (its root left open onto the wall).
VolumeCheck check_volume_curved_wall(const mesh::Mesh& mesh, const std::vector<const surface::SurfaceMesh*>& body,
                                     const std::vector<const surface::SurfaceMesh*>& farfield,
                                     const surface::SurfaceMesh& wall,
                                     const std::vector<double>* known = nullptr);

}  // namespace semimesh::checks
