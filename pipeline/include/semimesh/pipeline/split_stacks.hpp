// Splitting the near field's layer stacks (near_field.hpp) into their boundary layers in one pass
// (ho::split_layers): every element along its own direction(s) with its family's layers (wing
// prisms along zeta into the wing's layers, wall prisms into the wall's, junction hexes across
// both), so every face shared by two stacks is cut the same way.
#pragma once

#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/nearfield/near_field.hpp"

#include <atomic>
#include <vector>

namespace semimesh::pipeline {

struct FamilySplit {
  ho::LayerDistribution distribution;
  ho::RatioField ratio;  ///< optional, per vertex (see split_layers.hpp)
};

struct StackSplit {
  mesh::Mesh mesh;
  /// [stacks] output index of each stack's first-layer piece (the one touching its body face in
  /// every direction)
  std::vector<std::size_t> first_layer;
  ho::SplitStats wing, wall;  ///< first-cell figures per family (zero when nothing of it was split)
  /// [mesh elements] the bounds the pieces inherit (split_layers); empty unless asked
  std::vector<ho::InheritedBounds> inherited;
};

/// Throws std::invalid_argument (from split_layers) when two stacks sharing a face would cut it
/// differently, naming both elements.
/// `progress` as split_layers'. inherit_bounds: fill `inherited`. The mesh is taken by value: a
/// caller that moves it in holds its nodes once (they move into the output). `entities`: the
/// output's edges and faces (ho::SplitEntities; Adopted for a caller that renumbers them next).
/// `ahead` (optional): the pieces' bounds derived before (piece_bounds_ahead), taken where they hold.
StackSplit split_stacks(mesh::Mesh mesh, const std::vector<nearfield::LayerStack>& stacks,
                        const FamilySplit& wing, const FamilySplit& wall, const ProgressCallback& progress = {},
                        bool inherit_bounds = false, ho::SplitEntities entities = ho::SplitEntities::Canonical,
                        const ho::PieceBoundsAhead* ahead = nullptr);

/// The bounds split_stacks(..., inherit_bounds = true) derives for the pieces, derived before the
/// split (ho::piece_bounds_ahead) on `curved`, a mesh whose elements are the first ones of the mesh
/// split later (e.g. beside TetGen's process): for the stacks whose elements it has. `stop` as
/// ho::piece_bounds_ahead's.
ho::PieceBoundsAhead piece_bounds_ahead(const mesh::Mesh& curved, const std::vector<nearfield::LayerStack>& stacks,
                                        const FamilySplit& wing, const FamilySplit& wall,
                                        const std::atomic<bool>& stop);

}  // namespace semimesh::pipeline
