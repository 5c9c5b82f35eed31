// Conformity of a volume mesh: every face of every element is either shared by exactly two
// elements that see the same nodes from opposite sides, or lies on the boundary as exactly one
// boundary face of one named group.
//
// The check rebuilds the faces from the elements' canonical node lists (ho::faces order) instead of
// trusting the mesh's own face entities, so it also catches a builder that linked the wrong nodes.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace semimesh::checks {

struct FaceProblem {
  enum class Kind {
    SharedByMoreThanTwo,     ///< three or more elements use the face
    SameSide,                ///< two elements use it with the same orientation: they overlap
    DifferentNodes,          ///< the users of the face do not give it the same (high-order) nodes
    Unmatched,               ///< one element uses it and it is not a boundary face: a gap or hole
    BoundaryOnInteriorFace,  ///< a boundary face lies between two elements
    BoundaryRepeated,        ///< the face is a boundary face more than once (one group or several)
    BoundaryWithoutElement,  ///< a boundary face that no element has
  };
  Kind kind = Kind::Unmatched;
  std::vector<mesh::NodeId> vertices;       ///< [3 or 4] sorted vertex ids of the face
  std::vector<std::size_t> elements;        ///< elements using it
  std::vector<std::size_t> boundary_faces;  ///< boundary faces on it
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  /// One line: what is wrong, where (centroid), which elements and boundary faces (with groups).
  std::string describe(const mesh::Mesh& mesh) const;
};

std::string to_string(FaceProblem::Kind kind);

struct ConformityResult {
  std::size_t interior_faces = 0;  ///< faces shared by exactly two elements
  std::size_t boundary_faces = 0;  ///< faces of one element carrying exactly one boundary face
  std::vector<FaceProblem> problems;  ///< sorted by (kind, vertices)
  bool ok() const { return problems.empty(); }
};

/// Whether check_conformity gives its problems' centroids (FaceProblem::centroid), the one thing
/// it reads node positions for.
enum class Located { Yes, Later };

/// Sort-based check, O(number of faces). Located::Later: the problems' centroids stay zero (for a
/// caller that runs the check while another thread moves the nodes; locate_problems gives them).
ConformityResult check_conformity(const mesh::Mesh& mesh, Located located = Located::Yes);

/// The centroid of each problem's vertices, at the mesh's current node positions.
void locate_problems(const mesh::Mesh& mesh, ConformityResult& result);

/// The same verdict by comparing every face with every other one, O(faces^2), and every use's
/// nodes node by node (check_conformity takes uses that read the same face and edge entities as
/// giving the same nodes): a slow reference for tests on small meshes.
ConformityResult check_conformity_brute_force(const mesh::Mesh& mesh);

}  // namespace semimesh::checks
