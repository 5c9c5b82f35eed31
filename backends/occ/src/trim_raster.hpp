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
//
// The band left can then be answered from the loops' polylines (keep_polylines()): a point of a
// near sub-cell farther from every polyline than the polylines are from their curves (twice the
// largest midpoint deviation) plus the classifier's tolerance has the polygons' class: the
// parity of the polyline crossings of the shortest ray along u or v from it to a classified
// sub-cell, whose class is known (a ray that passes an edge's open end tries the next). A point
// within half the classifier's certain tolerance of a loop is on it: inside (the marches along a
// side of the parameter box). Only the points between, a thin band, still go to OCC.
#pragma once

#include "semimesh/cad/types.hpp"

#include <array>
#include <cstdint>
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

  /// The exact test's tolerances, in the parameters: within `boundary` of a loop it may count a
  /// point as on the boundary, within `vertex` of a vertex too, and within `on` of a loop it surely does.
  struct Tolerances {
    double boundary = 0.0;
    double vertex = 0.0;
    double on = 0.0;
  };
  /// After a successful refine(): keeps the loops' polylines so that lookup() answers in near
  /// sub-cells too, away from them. `loops` as given to refine(), one per edge (its first and last
  /// samples are its open ends: vertices); `midpoints[l][k]` the curve's point halfway in parameter
  /// between samples k and k + 1 of loop l (a segment's curve is taken to stay within twice that
  /// point's distance from it). A point within kOnFraction of `on` from a loop is answered inside
  /// (a march along a side of the parameter box); within the band (`boundary` + the largest
  /// deviation) of a loop or within `vertex` of a vertex, it is left to the exact test. Returns
  /// false, keeping nothing, when the band or the vertices' tolerance would reach the classified
  /// sub-cells (refine()'s margin - 1/2 sub-cells), when two edges' ends are a sub-cell apart, or
  /// when there is no refinement.
  bool keep_polylines(const std::vector<std::vector<cad::Vec2>>& loops,
                      const std::vector<std::vector<cad::Vec2>>& midpoints, const Tolerances& tolerances);
  /// The fraction of keep_polylines()' `on_tolerance` within which a point is on a loop: a margin
  /// for the classifier's own polygon (OCC tests against it first, within its tolerance).
  static constexpr double kOnFraction = 0.5;

  /// Inside or outside when uv lies in a classified cell or sub-cell, or in a near sub-cell away
  /// from the kept polylines; nothing when it lies near a loop or outside the box (then the exact
  /// test answers).
  std::optional<bool> lookup(const cad::Vec2& uv) const;

  /// Number of cells of each kind, for tests and benches: {near, inside, outside}.
  std::array<int, 3> census() const;
  /// The same over the sub-cells of the refined near cells (all 0 before refine()).
  std::array<int, 3> sub_census() const;
  /// Sub-cells per cell along u and v (0 when not refined).
  int refinement() const { return m_; }
  /// The width, in the parameters, of the band along the kept polylines left to the exact test (0
  /// when no polylines are kept).
  double polyline_band() const { return band_; }

 private:
  enum Cell : unsigned char { kUnknown, kNear, kInside, kOutside };
  std::optional<std::array<int, 2>> cell_of(const cad::Vec2& uv) const;
  /// The sub-cell of uv inside cell c, along u and v (in [0, m)).
  std::array<int, 2> sub_cell_of(const cad::Vec2& uv, const std::array<int, 2>& c) const;
  /// Global sub-cell (I, J)'s class: its own in a refined cell, its cell's otherwise.
  Cell sub_class(long I, long J) const;
  /// The index in sub_cells_ of global sub-cell (I, J), or -1 in a cell that is not refined.
  long sub_index(long I, long J) const;
  /// The distance in the parameters from p (in sub-cell units) to kept segment `segment`.
  double uv_distance(const cad::Vec2& p, std::uint32_t segment) const;
  /// The class of p (in sub-cell units) from the kept polylines, or nothing (see keep_polylines);
  /// `only_on`: inside when p is on a loop, else nothing.
  std::optional<bool> by_polylines(const cad::Vec2& p, bool only_on) const;
  /// The global sub-cell at `along` on axis `axis` (0: u, 1: v) and `across` on the other.
  std::array<long, 2> ray_cell(int axis, long along, long across) const;
  /// The ray (axis * 2 + (direction < 0)) from p that passes the fewest sub-cells before a
  /// classified one, the first of them on a tie; -1 when all four leave the box first.
  int shortest_ray(const cad::Vec2& p) const;
  /// The polygons' class of p from the crossings of the ray from p along `axis` (0: u, 1: v) in
  /// `direction` (+1 or -1) up to the first classified sub-cell; nothing when it passes an open
  /// end or leaves the box.
  std::optional<bool> along_ray(const cad::Vec2& p, int axis, int direction) const;

  std::array<cad::Interval, 2> box_;
  int n_;
  cad::Vec2 cell_;
  std::vector<Cell> cells_;  // row-major: i (u) + n j (v)
  int m_ = 0;                 // sub-cells per cell along u and v once refined
  int shift_ = 0;             // m_ = 2^shift_
  int sub_margin_ = 0;        // refine()'s margin
  std::vector<int> block_;    // per cell: its block of m x m sub-cells in sub_cells_, or -1
  std::vector<Cell> sub_cells_;  // blocks, each row-major: a (u) + m b (v)
  // The kept polylines, in sub-cell units from the box's corner: (u - u_lo) / sub-cell width, ...
  std::vector<std::array<cad::Vec2, 2>> segments_;
  std::vector<double> deviation_;  // per segment: how far its curve may be from it (in the parameters)
  std::vector<cad::Vec2> open_ends_;
  std::vector<double> end_reach_;  // per open end: rays within it are blocked (band_ or the gap to the next end)
  // Per entry of sub_cells_: the segments (ids) and open ends (segments_.size() + id) within band_
  // of it, in items_[first_[k], first_[k + 1]).
  std::vector<std::uint32_t> first_, items_;
  cad::Vec2 sub_ = cad::Vec2::Zero();  // a sub-cell's size along u and v
  double band_ = 0.0;                   // in the parameters
  double vertex_ = 0.0;                 // in the parameters
  double on_ = 0.0;                     // in the parameters
};

}  // namespace semimesh::occ
