#include "semimesh/cad/model.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace semimesh::cad {
namespace {

[[noreturn]] void topology_error(const std::string& backend, const std::string& what) {
  throw CadError(CadError::Kind::Geometry, "backend '" + backend + "': inconsistent topology: " + what);
}

// Adds the curve's extreme points per axis: 32 samples, then golden-section search around the
// extreme sample, so that a coordinate maximum between two samples is not missed.
void add_curve_extremes(const Curve& c, BBox& box) {
  constexpr int kSamples = 32;
  const Interval range = c.bounds();
  const double h = range.length() / kSamples;
  std::vector<Vec3> p(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) box.add(p[i] = c.point(range.lo + h * i));
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {+1.0, -1.0}) {
      int best = 0;
      for (int i = 1; i <= kSamples; ++i)
        if (sign * p[i][axis] > sign * p[best][axis]) best = i;
      double a = range.clamp(range.lo + h * (best - 1)), b = range.clamp(range.lo + h * (best + 1));
      const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
      for (int it = 0; it < 60 && b - a > 1e-15 * std::max(1.0, range.length()); ++it) {
        double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
        if (sign * c.point(x1)[axis] > sign * c.point(x2)[axis]) b = x2;
        else a = x1;
      }
      box.add(c.point(0.5 * (a + b)));
    }
}

}  // namespace

Model::~Model() = default;

int Model::add_vertex(const Vec3& point, std::string name) {
  int id = num_vertices();
  vertices_.push_back(Vertex{id, point, std::move(name)});
  return id;
}

int Model::add_curve(std::unique_ptr<Curve> curve, int start_vertex, int end_vertex) {
  if (curve->id() != num_curves())
    topology_error(backend_, "curve added with id " + std::to_string(curve->id()) + ", expected " + std::to_string(num_curves()));
  curves_.push_back(std::move(curve));
  curve_vertices_.push_back({start_vertex, end_vertex});
  return num_curves() - 1;
}

int Model::add_surface(std::unique_ptr<Surface> surface, std::vector<Loop> loops) {
  if (surface->id() != num_surfaces())
    topology_error(backend_, "surface added with id " + std::to_string(surface->id()) + ", expected " + std::to_string(num_surfaces()));
  surfaces_.push_back(std::move(surface));
  loops_.push_back(std::move(loops));
  return num_surfaces() - 1;
}

void Model::set_units(std::string units, double scale_applied) {
  units_ = std::move(units);
  scale_applied_ = scale_applied;
}

void Model::finalize() {
  curve_surfaces_.assign(curves_.size(), {});
  vertex_curves_.assign(vertices_.size(), {});
  for (int c = 0; c < num_curves(); ++c) {
    for (int v : curve_vertices_[c]) {
      if (v < 0 || v >= num_vertices())
        topology_error(backend_, "curve " + std::to_string(c) + " ('" + curves_[c]->name() + "') names vertex " + std::to_string(v));
    }
    vertex_curves_[curve_vertices_[c][0]].push_back(c);
    if (curve_vertices_[c][1] != curve_vertices_[c][0]) vertex_curves_[curve_vertices_[c][1]].push_back(c);
  }
  for (int s = 0; s < num_surfaces(); ++s) {
    const std::string where = "surface " + std::to_string(s) + " ('" + surfaces_[s]->name() + "')";
    if (loops_[s].empty()) topology_error(backend_, where + " has no loop");
    for (size_t l = 0; l < loops_[s].size(); ++l) {
      const auto& uses = loops_[s][l].uses;
      if (uses.empty()) topology_error(backend_, where + " loop " + std::to_string(l) + " is empty");
      // All ids first: the closure check below reads the next use's curve too.
      for (const CurveUse& u : uses)
        if (u.curve < 0 || u.curve >= num_curves())
          topology_error(backend_, where + " loop " + std::to_string(l) + " names curve " + std::to_string(u.curve));
      for (size_t k = 0; k < uses.size(); ++k) {
        const CurveUse& u = uses[k];
        curve_surfaces_[u.curve].push_back(SurfaceUse{s, u.forward});
        const CurveUse& next = uses[(k + 1) % uses.size()];
        int end = curve_vertices_[u.curve][u.forward ? 1 : 0];
        int start = curve_vertices_[next.curve][next.forward ? 0 : 1];
        if (end != start)
          topology_error(backend_, where + " loop " + std::to_string(l) + " is not closed: curve " + std::to_string(u.curve) +
                                       " ends at vertex " + std::to_string(end) + " but curve " + std::to_string(next.curve) +
                                       " starts at vertex " + std::to_string(start));
      }
    }
  }
  closed_ = num_curves() > 0;
  for (int c = 0; c < num_curves(); ++c)
    closed_ = closed_ && (curve_surfaces_[c].size() == 2 || (curves_[c]->is_degenerate() && curve_surfaces_[c].size() == 1));

  bbox_ = BBox{};
  for (const Vertex& v : vertices_) bbox_.add(v.point);
  for (const auto& c : curves_) add_curve_extremes(*c, bbox_);
  for (const auto& s : surfaces_) {
    auto box = s->bounds();
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 16; ++j) {
        Vec2 uv(box[0].lo + box[0].length() * i / 16, box[1].lo + box[1].length() * j / 16);
        if (s->contains(uv)) bbox_.add(s->point(uv));
      }
  }
  finalized_ = true;
}

namespace {
template <class T>
const T& checked(const std::vector<T>& v, int id, const char* what, const std::string& backend) {
  if (id < 0 || id >= static_cast<int>(v.size()))
    throw CadError(CadError::Kind::Geometry, "backend '" + backend + "': no " + what + " with id " + std::to_string(id) +
                                                 " (model has " + std::to_string(v.size()) + ")");
  return v[id];
}
}  // namespace

const Vertex& Model::vertex(int id) const { return checked(vertices_, id, "vertex", backend_); }
const Curve& Model::curve(int id) const { return *checked(curves_, id, "curve", backend_); }
const Surface& Model::surface(int id) const { return *checked(surfaces_, id, "surface", backend_); }
const std::vector<Loop>& Model::loops(int surface) const { return checked(loops_, surface, "surface", backend_); }
const std::vector<SurfaceUse>& Model::surfaces_of_curve(int curve) const {
  return checked(curve_surfaces_, curve, "curve", backend_);
}
std::array<int, 2> Model::curve_vertices(int curve) const { return checked(curve_vertices_, curve, "curve", backend_); }
const std::vector<int>& Model::curves_of_vertex(int vertex) const {
  return checked(vertex_curves_, vertex, "vertex", backend_);
}

bool Model::is_seam(int surface, int curve) const {
  bool forward = false, reversed = false;
  for (const SurfaceUse& use : surfaces_of_curve(curve))
    if (use.surface == surface) (use.forward ? forward : reversed) = true;
  return forward && reversed;
}

std::optional<int> Model::find_surface(const std::string& name) const {
  for (const auto& s : surfaces_)
    if (s->name() == name) return s->id();
  return std::nullopt;
}

}  // namespace semimesh::cad
