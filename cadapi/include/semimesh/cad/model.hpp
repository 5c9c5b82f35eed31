// A loaded CAD model: entities and their topology.
//
// Backends fill a Model through add_vertex / add_curve / add_surface and then call finalize(),
// which derives the inverse adjacency (curve -> surfaces, vertex -> curves), the bounding box and
// the closedness check once. Ids are dense, 0-based indices in insertion order.
//
// Topology contract:
//  - each surface has loops, the outer one first; a loop is a closed chain of curve uses, each
//    use walking its curve forward (t0 -> t1) or reversed;
//  - walking a loop, the face's material lies on the left when seen from the fluid side (outer
//    loop counter-clockwise around the fluid normal);
//  - every curve records its end vertices (equal for a closed curve).
#pragma once

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"
#include "semimesh/cad/types.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace semimesh::cad {

struct Vertex {
  int id = -1;
  Vec3 point;
  std::string name;
};

/// A curve as walked by a loop.
struct CurveUse {
  int curve = -1;
  bool forward = true;  ///< walks t0 -> t1
};

/// A closed chain of curve uses bounding a surface.
struct Loop {
  std::vector<CurveUse> uses;
};

/// A surface bounded by a curve, and the direction the surface's loop walks that curve.
struct SurfaceUse {
  int surface = -1;
  bool forward = true;
};

class Model {
 public:
  explicit Model(std::string backend) : backend_(std::move(backend)) {}
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;
  ~Model();

  // ---- building (backends only) ----
  int add_vertex(const Vec3& point, std::string name = {});
  /// Takes ownership; `curve->id()` must equal the number of curves added before it.
  int add_curve(std::unique_ptr<Curve> curve, int start_vertex, int end_vertex);
  /// Takes ownership; `surface->id()` must equal the number of surfaces added before it.
  int add_surface(std::unique_ptr<Surface> surface, std::vector<Loop> loops);
  void set_units(std::string units, double scale_applied);
  /// Why the model is in that unit, for users: e.g. "declared by the file (STEP: MILLI METRE)".
  void set_units_origin(std::string origin) { units_origin_ = std::move(origin); }
  /// What the backend changed in the file's geometry to make it a model (sewing a gap, closing an
  /// opening), one sentence each, for users: e.g. "sewn 36 edge pairs at tolerance 1.4e-05".
  void add_repair(std::string repair) { repairs_.push_back(std::move(repair)); }
  void set_tolerance(double tolerance) { tolerance_ = tolerance; }
  void set_thread_safe(bool thread_safe) { thread_safe_ = thread_safe; }
  /// Keeps a backend object (e.g. the OCC shape) alive as long as the model.
  void keep_alive(std::shared_ptr<void> owner) { owners_.push_back(std::move(owner)); }
  /// Derives adjacency and bbox; validates ids. Throws CadError on inconsistent topology.
  void finalize();

  // ---- queries ----
  const std::string& backend() const { return backend_; }
  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_curves() const { return static_cast<int>(curves_.size()); }
  int num_surfaces() const { return static_cast<int>(surfaces_.size()); }

  const Vertex& vertex(int id) const;
  const Curve& curve(int id) const;
  const Surface& surface(int id) const;

  /// Loops of a surface, outer first.
  const std::vector<Loop>& loops(int surface) const;
  /// Surfaces a curve bounds, with the direction each one's loop walks it.
  const std::vector<SurfaceUse>& surfaces_of_curve(int curve) const;
  /// {start vertex, end vertex} of a curve.
  std::array<int, 2> curve_vertices(int curve) const;
  /// Curves that start or end at a vertex.
  const std::vector<int>& curves_of_vertex(int vertex) const;

  /// Whether the loops of `surface` walk `curve` twice, once each way: a seam of a periodic face,
  /// whose two sides are the same curve one period apart in the face's parameters.
  bool is_seam(int surface, int curve) const;

  /// First surface with that name, if any.
  std::optional<int> find_surface(const std::string& name) const;

  /// Box around all entities (from sampled curves and surfaces, computed in finalize()).
  const BBox& bbox() const { return bbox_; }
  /// Geometric tolerance of the model in its unit.
  double tolerance() const { return tolerance_; }
  /// Unit of all coordinates ("mm", "m", "chord", ...) and the factor applied at load.
  const std::string& units() const { return units_; }
  double scale_applied() const { return scale_applied_; }
  /// Why units() is what it is (empty when the backend does not say).
  const std::string& units_origin() const { return units_origin_; }
  /// The backend's repairs of the file (add_repair), in the order made; empty: taken as it is.
  const std::vector<std::string>& repairs() const { return repairs_; }
  /// Watertight: every curve bounds exactly two surfaces (seam curves: one surface, twice;
  /// degenerate curves are points and bound one surface once).
  bool is_closed() const { return closed_; }
  /// Whether queries may run concurrently from several threads.
  bool thread_safe() const { return thread_safe_; }

 private:
  std::vector<std::shared_ptr<void>> owners_;  // first: destroyed after the entities using it
  std::string backend_;
  std::vector<Vertex> vertices_;
  std::vector<std::unique_ptr<Curve>> curves_;
  std::vector<std::array<int, 2>> curve_vertices_;
  std::vector<std::unique_ptr<Surface>> surfaces_;
  std::vector<std::vector<Loop>> loops_;
  std::vector<std::vector<SurfaceUse>> curve_surfaces_;
  std::vector<std::vector<int>> vertex_curves_;
  BBox bbox_;
  double tolerance_ = 1e-7;
  std::string units_ = "unknown";
  std::string units_origin_;
  std::vector<std::string> repairs_;
  double scale_applied_ = 1.0;
  bool closed_ = false;
  bool thread_safe_ = true;
  bool finalized_ = false;
};

}  // namespace semimesh::cad
