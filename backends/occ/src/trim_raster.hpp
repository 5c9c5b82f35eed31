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

  /// Inside or outside when uv lies in a classified cell; nothing when it lies in a near cell or
  /// outside the box (then the exact test answers).
  std::optional<bool> lookup(const cad::Vec2& uv) const;

  /// Number of cells of each kind, for tests and benches: {near, inside, outside}.
  std::array<int, 3> census() const;

 private:
  enum Cell : unsigned char { kUnknown, kNear, kInside, kOutside };
  std::optional<std::array<int, 2>> cell_of(const cad::Vec2& uv) const;

  std::array<cad::Interval, 2> box_;
  int n_;
  cad::Vec2 cell_;
  std::vector<Cell> cells_;  // row-major: i (u) + n j (v)
};

}  // namespace semimesh::occ
