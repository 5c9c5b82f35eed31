// Which parts of a face's parameter box lie wholly inside or wholly outside its trimming loops, so
// that most point-in-face queries skip the exact classifier (OCC's polygon test runs over every
// vertex of the loops' discretisation: on a wall face holding a finely sampled root loop, or on a
// many-patch wing, it dominated the size field's shell limits).
//
// The box is cut into n x n cells. Every cell within `margin` cells of a loop sample is "near":
// its points go to the exact test. With loop samples at most half a cell apart along each
// parameter, a loop never leaves its samples' cells and their neighbours, so the other cells fall
// into 4-connected regions that no loop crosses: each region is inside or outside as a whole, and
// the exact test at one of its cell centres tells which. A margin of 1 + the classifier's parameter
// tolerance in cells keeps the points the tolerance counts as "on" the boundary in near cells.
//
// The near cells can then be refined (refine()): each is cut into m x m sub-cells, marked near the
// same way from samples at most half a sub-cell apart, and the other sub-cells classified by region
// (a region of sub-cells no loop crosses that touches a classified cell takes its class; otherwise
// one exact test). The band left to the exact test is then m times thinner: where queries crowd the
// face's edges (the size field's marches along a wing's root, tip and trailing edge) most of them
// were in it.
#pragma once

#include "semimesh/cad/types.hpp"

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace semimesh::occ {

class TrimRaster {
 public:
  /// An empty raster over `box` (both lengths > 0) with n x n cells (n >= 2).
  TrimRaster(const std::array<cad::Interval, 2>& box, int n);

  /// Cell sizes along u and v: loop samples must be at most half of them apart.
  cad::Vec2 cell_size() const { return cell_; }

  /// Marks the cells within `margin` (>= 1) cells of each sample as near.
  void mark_loop(const std::vector<cad::Vec2>& samples, int margin);

  /// Classifies every other cell, calling `exact` once per region at a cell centre.
  void classify(const std::function<bool(const cad::Vec2&)>& exact);

  /// After classify(): cuts every near cell into m x m sub-cells (m a power of 2), marks the sub-cells within
  /// `margin` (1 <= margin <= m) sub-cells of each sample of `loops` as near (the samples at most
  /// half a sub-cell apart along u and v, every loop of the face) and classifies the other sub-cells
  /// by region: a region touching a classified cell takes its class, any other calls `exact` once.
  /// Returns false, leaving the raster as classify() left it, when a near sub-cell would fall in a
  /// classified cell or a region touches both classes (samples too coarse for the loops).
  bool refine(int m, const std::vector<std::vector<cad::Vec2>>& loops, int margin,
              const std::function<bool(const cad::Vec2&)>& exact);

  /// Inside or outside when uv lies in a classified cell or sub-cell; nothing when it lies in a near
  /// one or outside the box (then the exact test answers).
  std::optional<bool> lookup(const cad::Vec2& uv) const;

  /// Number of cells of each kind, for tests and benches: {near, inside, outside}.
  std::array<int, 3> census() const;
  /// The same over the sub-cells of the refined near cells (all 0 before refine()).
  std::array<int, 3> sub_census() const;
  /// Sub-cells per cell along u and v (0 when not refined).
  int refinement() const { return m_; }

 private:
  enum Cell : unsigned char { kUnknown, kNear, kInside, kOutside };
  std::optional<std::array<int, 2>> cell_of(const cad::Vec2& uv) const;
  /// The sub-cell of uv inside cell c, along u and v (in [0, m)).
  std::array<int, 2> sub_cell_of(const cad::Vec2& uv, const std::array<int, 2>& c) const;

  std::array<cad::Interval, 2> box_;
  int n_;
  cad::Vec2 cell_;
  std::vector<Cell> cells_;  // row-major: i (u) + n j (v)
  int m_ = 0;                 // sub-cells per cell along u and v once refined
  std::vector<int> block_;    // per cell: its block of m x m sub-cells in sub_cells_, or -1
  std::vector<Cell> sub_cells_;  // blocks, each row-major: a (u) + m b (v)
};

}  // namespace semimesh::occ
