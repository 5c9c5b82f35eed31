#include "model_as_run.hpp"

#include "semimesh/pipeline/pipeline.hpp"
#include "semimesh/surface/cad_roles.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace semimesh::app {

std::array<double, 3> rounded(const cad::Vec3& x) {
  const double scale = std::max(1.0, x.cwiseAbs().maxCoeff());
  std::array<double, 3> out{};
  for (int k = 0; k < 3; ++k)
    out[k] = std::abs(x[k]) < 1e-12 * scale ? 0.0 : std::stod(fmt::format("{:.12g}", x[k]));
  return out;
}

namespace {

std::vector<std::string> join_entries(const std::vector<int>& faces) {
  std::vector<std::string> out;
  for (int s : faces) out.push_back("#" + std::to_string(s));
  return out;
}

// Whether every curve of the part's faces bounds two face uses (a seam counts twice): a closed part,
// not faces of one body left unsewn (an upper and a lower skin overlap too).
bool closed_part(const cad::Model& model, const std::vector<int>& faces) {
  std::set<int> curves;
  for (int s : faces)
    for (const cad::Loop& loop : model.loops(s))
      for (const cad::CurveUse& use : loop.uses) curves.insert(use.curve);
  return std::all_of(curves.begin(), curves.end(), [&](int c) { return model.surfaces_of_curve(c).size() == 2; });
}

// Where a wall part's end is cut: at least this share of its length inside it (a fuselage's flat
// end is left out with the box), and further in while the wall there leans more than kCutLean from
// square to the cut (a nose or tail cone: the wall layer meets the box's faces within 0.1 rad).
constexpr double kWallEndInset = 0.02;
constexpr double kCutLean = 0.05;

// The most the wall part's normals lean along `axis` (radians from square to a cut across it) at
// the section `at`, sampled on a grid of each face within `band` of it; 0 where none is sampled.
double lean_at(const cad::Model& model, const std::vector<int>& faces, int axis, double at, double band) {
  constexpr int kGrid = 64;
  double lean = 0.0;
  for (int s : faces) {
    const cad::Surface& face = model.surface(s);
    const auto box = face.bounds();
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; j <= kGrid; ++j) {
        const cad::Vec2 uv(box[0].lo + box[0].length() * i / kGrid, box[1].lo + box[1].length() * j / kGrid);
        if (!face.contains(uv) || std::abs(face.point(uv)[axis] - at) > band) continue;
        const double along = std::abs(face.normal(uv)[axis]);
        if (std::isfinite(along)) lean = std::max(lean, std::asin(std::min(1.0, along)));
      }
  }
  return lean;
}

// The join of an assembly's two overlapping parts, the box kBoxChords of the body's streamwise (x)
// extent around it, clipped inside the wall part's ends along the wall part's longest axis so that
// the box crosses it (a fuselage runs through it). Nothing when the clipped box would cut the body.
std::optional<AssemblyJoin> assembly_join(const cad::Model& model, const surface::OverlappingParts& parts) {
  const cad::BBox& b = parts.body_box;
  const cad::BBox& w = parts.wall_box;
  const double chord = b.hi.x() - b.lo.x();
  if (!(chord > 0.0)) return std::nullopt;
  AssemblyJoin join;
  join.body = join_entries(parts.body);
  join.wall = join_entries(parts.wall);
  int axis = 0;
  (w.hi - w.lo).maxCoeff(&axis);
  for (int k = 0; k < 3; ++k) {
    join.box[k] = b.lo[k] - kBoxChords * chord;
    join.box[k + 3] = b.hi[k] + kBoxChords * chord;
  }
  const double length = w.hi[axis] - w.lo[axis], step = kWallEndInset * length;
  join.box[axis] = std::max(join.box[axis], w.lo[axis] + step);
  join.box[axis + 3] = std::min(join.box[axis + 3], w.hi[axis] - step);
  // Each end moved in towards the body, a chord short of it at most, while the wall leans there.
  while (join.box[axis] + step < b.lo[axis] - chord && lean_at(model, parts.wall, axis, join.box[axis], step) > kCutLean)
    join.box[axis] += step;
  while (join.box[axis + 3] - step > b.hi[axis] + chord &&
         lean_at(model, parts.wall, axis, join.box[axis + 3], step) > kCutLean)
    join.box[axis + 3] -= step;
  if (!(join.box[axis] < b.lo[axis] && join.box[axis + 3] > b.hi[axis])) return std::nullopt;
  // A body running through the wall part across its length (a full-span wing through a fuselage)
  // stands on it twice: the box keeps the side above the wall part's middle plane across that
  // axis, the plane of symmetry of an aircraft's fuselage, and that side is its symmetry plane.
  const char* names = "xyz";
  std::string half;
  for (int a = 0; a < 3; ++a)
    if (a != axis && b.lo[a] < w.lo[a] && b.hi[a] > w.hi[a]) {
      const double middle = 0.5 * (w.lo[a] + w.hi[a]);
      join.box[a] = std::abs(middle) < 1e-9 * (w.hi - w.lo).norm() ? 0.0 : middle;
      join.symmetry = std::string(1, names[a]) + "min";
      half = fmt::format("; the body runs through the wall part along {}: a half model, the box's side {} on the "
                         "wall part's middle plane {} = {:.6g} (farfield.symmetry = \"{}\": its faces the boundary "
                         "group \"symmetry\")",
                         names[a], join.symmetry, names[a], join.box[a], join.symmetry);
      break;
    }
  for (double& x : join.box) x = std::stod(fmt::format("{:.6g}", x));
  join.why = fmt::format("the file holds two overlapping parts that share no curve: the body {} joined to the wall "
                         "part {} at load; the far field a box {} chords of the body's x extent around it, its "
                         "ends along {} (the wall part's longest axis) at {} and {}: at least {} % of its length "
                         "inside its ends, where it leans less than {} rad from square to them",
                         fmt::join(join.body, ", "), fmt::join(join.wall, ", "), kBoxChords, names[axis],
                         join.box[axis], join.box[axis + 3], 100 * kWallEndInset, kCutLean) + half;
  return join;
}

// The file loaded again with what `load` builds around it (a wall plane and a box, or a join),
// as `run` will load it: the parameters init writes, the caller's other ones kept.
std::unique_ptr<cad::Model> load_built(const cad::Registry& registry, const std::string& backend,
                                       const std::string& path, const cad::Params& params,
                                       pipeline::GeometryConfig load) {
  load.backend = backend;
  load.source = path;
  cad::Source source = pipeline::cad_source(load);
  for (const auto& [key, value] : params.all())
    if (!source.params.has(key)) source.params.set(key, value);
  return registry.load(backend, source);
}

}  // namespace

ModelAsRun load_model_as_run(const cad::Registry& registry, const std::string& backend, const std::string& path,
                             const cad::Params& params) {
  ModelAsRun out{registry.load(backend, cad::Source{path, params}), std::nullopt, std::nullopt};
  if (surface::has_wall_with_root_loop(*out.model)) return out;
  // Separate parts reaching into each other are no body on a wall, whatever else they look like
  // (a wing's own trailing-edge seam meeting its open root would pass for a fuselage's): two of
  // them are joined as `run` will join them; more are left to the user to choose from.
  if (const std::optional<surface::OverlappingParts> parts = surface::find_overlapping_parts(*out.model);
      parts && parts->count == 2 && !params.has("occ.join_body") && closed_part(*out.model, parts->body) &&
      closed_part(*out.model, parts->wall))
    if (std::optional<AssemblyJoin> join = assembly_join(*out.model, *parts)) {
      pipeline::GeometryConfig load;
      load.join.body = join->body;
      load.join.wall = join->wall;
      load.farfield_shape.box = join->box;
      out.model = load_built(registry, backend, path, params, std::move(load));
      out.join = std::move(join);
      return out;
    }
  surface::refuse_overlapping_parts(*out.model);
  // A wall may be there whose seam hides the root (its planar faces would be taken for root caps).
  surface::refuse_seam_through_root(*out.model);
  std::optional<surface::RootPlane> root = surface::find_root_plane(*out.model);
  if (!root) surface::detect_cad_roles(*out.model);  // throws, saying what is missing
  pipeline::GeometryConfig load;
  load.wall_plane.point = rounded(root->point);
  load.wall_plane.normal = rounded(root->normal);
  load.farfield_shape.box_chords = kBoxChords;
  out.model = load_built(registry, backend, path, params, std::move(load));
  out.root = std::move(root);
  return out;
}

}  // namespace semimesh::app
