// Steps of the H-type near field (h_shell.cpp, wake_block.cpp) with a contract of their own, here
// so their tests can reach them: finding the trailing edge the wake is swept from, and the wake's
// streamwise stations.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/h_shell.hpp"
#include "semimesh/nearfield/o_shell.hpp"

#include <set>
#include <vector>

namespace semimesh::nearfield::detail {

/// A sharp trailing edge: of the curves between two body surfaces that leave the wall (a vertex on
/// a body-wall curve), the one whose wall vertex lies farthest downstream along `d` (the leading
/// edge is the other one of a wing's section); -1 when there is none.
int sharp_trailing_edge(const cad::Model& model, const BodyRoles& roles, const Vec3& d);

/// The trailing-edge base's faces, ascending: `root_face` (the base on the root) and the body faces
/// reached from it across shared curves that face the way their neighbour in the base does (mean
/// outward normals within 45 degrees) and are no slivers (as trailing_edge_continuation's): a base
/// CAD tools split along the span into an upper and a lower half (OpenVSP), or across it at a crank
/// (one face per panel), or both. The skins beside the base face across the stream and the tip
/// along the span: they stay out; so do the tip's slivers at the trailing edge (OpenVSP's M6).
std::vector<int> trailing_edge_base(const cad::Model& model, const BodyRoles& roles, int root_face);

/// Where the trailing edge goes on past the base faces `base` (blunt; trailing_edge_base) or the
/// sharp edge's curve `crack` (empty or -1 for the other): a body surface across one of the base's
/// curves that borders none of the base's other body neighbours (a tip borders the sides; a cranked
/// wing's outboard base, were it not part of the base, would border only its own panel's sides), or
/// a curve at one of the crack's ends between two body surfaces that are neither of the crack's
/// sides (the outboard panel's trailing edge; a tip's curves have a side on one hand). Returns that
/// surface or curve id, -1 when the trailing edge ends at the tip; of several such surfaces the one
/// facing most nearly as the base (OpenVSP's M6 without its base's other half: that half, not the
/// skin beside it). Faces whose longest curve, and curves, under a tenth of the base's longest
/// curve or the crack's length are slivers, not panels (the ONERA M6's tip faces at its trailing
/// edge).
int trailing_edge_continuation(const cad::Model& model, const BodyRoles& roles, const std::vector<int>& base,
                               int crack);

/// The trailing-edge base's flat corners: CAD vertices where its two curves meet at more than 150
/// degrees inside the face (a revolved tip's rounded trailing edge continues the base's sides
/// tangentially: the NekMesh wing's base is a rectangle capped by a half disc). A structured quad
/// there has two edges along one tangent line: curved onto the CAD its Jacobian vanishes at that
/// corner and a hex swept from it is invalid at order >= 2.
std::set<int> flat_base_corners(const cad::Model& model, int base);

/// [layers + 1] streamwise stations 0 = s_0 < ... < s_K = length, each cell `growth` times the
/// previous one.
std::vector<double> wake_stations(const WakeParams& wake);

/// [cells + 1] wake_stations(wake), then on to `distance` (> wake.length): each further cell
/// `growth` times the previous one up to wake.outlet_cell, all of them scaled so the last station
/// is `distance` exactly. Just wake_stations scaled to `distance` when that is no longer than
/// wake.length.
std::vector<double> wake_stations_to(const WakeParams& wake, double distance);

}  // namespace semimesh::nearfield::detail
