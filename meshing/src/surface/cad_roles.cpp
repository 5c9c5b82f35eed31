#include "semimesh/surface/cad_roles.hpp"

#include "semimesh/cad/labels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace semimesh::surface {
namespace {

using cad::Vec2;
using cad::Vec3;

constexpr int kCurveSamples = 12;
constexpr int kFaceGrid = 9;
// A base is narrow when its root curves are shorter than this fraction of the root chord, and lies
// at the downstream end when its root points average within this fraction of the chord from it.
constexpr double kNarrowFraction = 0.1;
constexpr double kDownstreamFraction = 0.1;
// A base's root runs across the stream: along it by less than this fraction of its length (the
// thin faces closing a sharp trailing edge run along the stream: they are part of the skin).
constexpr double kAcrossFraction = 0.5;
// A tip is flat across the span: its extent along the span below this fraction of its chord.
constexpr double kFlatTipFraction = 0.25;

[[noreturn]] void fail(const std::string& message) { throw CadRoleError("CAD roles: " + message); }

std::vector<Vec3> curve_samples(const cad::Curve& curve) {
  const cad::Interval b = curve.bounds();
  std::vector<Vec3> points;
  for (int i = 0; i <= kCurveSamples; ++i) points.push_back(curve.point(b.lo + b.length() * i / kCurveSamples));
  return points;
}

// Points of a face: its boundary curves and the inside points of a grid over its parameter box.
std::vector<Vec3> face_samples(const cad::Model& model, int s) {
  std::vector<Vec3> points;
  for (const cad::Loop& loop : model.loops(s))
    for (const cad::CurveUse& use : loop.uses) {
      const auto c = curve_samples(model.curve(use.curve));
      points.insert(points.end(), c.begin(), c.end());
    }
  const cad::Surface& face = model.surface(s);
  const auto box = face.bounds();
  for (int i = 0; i <= kFaceGrid; ++i)
    for (int j = 0; j <= kFaceGrid; ++j) {
      const Vec2 uv(box[0].lo + box[0].length() * i / kFaceGrid, box[1].lo + box[1].length() * j / kFaceGrid);
      if (face.contains(uv)) points.push_back(face.point(uv));
    }
  return points;
}

// Curves of the face's inner loops that some other face also uses: where a body stands on it.
std::set<int> root_curves(const cad::Model& model, int wall) {
  std::set<int> curves;
  const auto& loops = model.loops(wall);
  for (std::size_t l = 1; l < loops.size(); ++l)
    for (const cad::CurveUse& use : loops[l].uses)
      for (const cad::SurfaceUse& u : model.surfaces_of_curve(use.curve))
        if (u.surface != wall) curves.insert(use.curve);
  return curves;
}

// Faces reached from the root curves across shared curves, never crossing the wall.
std::vector<int> faces_behind(const cad::Model& model, int wall, const std::set<int>& root) {
  std::vector<char> seen(model.num_surfaces(), 0);
  std::vector<int> stack;
  auto reach = [&](int curve) {
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(curve))
      if (u.surface != wall && !seen[u.surface]) {
        seen[u.surface] = 1;
        stack.push_back(u.surface);
      }
  };
  for (int c : root) reach(c);
  while (!stack.empty()) {
    const int s = stack.back();
    stack.pop_back();
    for (const cad::Loop& loop : model.loops(s))
      for (const cad::CurveUse& use : loop.uses) reach(use.curve);
  }
  std::vector<int> faces;
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (seen[s]) faces.push_back(s);
  return faces;
}

bool uses_any(const cad::Model& model, int s, const std::set<int>& curves) {
  for (const cad::Loop& loop : model.loops(s))
    for (const cad::CurveUse& use : loop.uses)
      if (curves.count(use.curve)) return true;
  return false;
}

// A face, planar or curved (a fuselage, a hub), can be the wall when faces stand on its inner loops
// and none of them also reaches its outer loop (which would make the "hole" a passage to the outer
// shell, not a body's root: a box face the fuselage runs through).
bool holds_a_body(const cad::Model& model, int wall) {
  const std::set<int> root = root_curves(model, wall);
  if (root.empty()) return false;
  std::set<int> outer;
  for (const cad::CurveUse& use : model.loops(wall).front().uses) outer.insert(use.curve);
  for (int s : faces_behind(model, wall, root))
    if (uses_any(model, s, outer)) return false;
  return true;
}

std::string labels(const cad::Model& model, const std::vector<int>& surfaces) {
  std::string text;
  for (int s : surfaces) text += (text.empty() ? "" : ", ") + cad::surface_label(model, s);
  return text.empty() ? "none" : text;
}

// A periodic face whose seam (a curve it uses twice) shares a vertex with a curve it shares with a
// curved face: a fuselage whose seam runs through the wing's root, which joins the root loop to
// the face's outer boundary instead of leaving it a hole. Returns the seam, or nothing.
std::optional<int> seam_through_root(const cad::Model& model, int s) {
  std::map<int, int> uses;
  for (const cad::Loop& loop : model.loops(s))
    for (const cad::CurveUse& use : loop.uses) ++uses[use.curve];
  std::set<int> root_vertices;
  for (const auto& [curve, count] : uses)
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(curve))
      if (count == 1 && u.surface != s && !model.surface(u.surface).is_planar())
        for (int v : model.curve_vertices(curve)) root_vertices.insert(v);
  for (const auto& [curve, count] : uses)
    if (count == 2)
      for (int v : model.curve_vertices(curve))
        if (root_vertices.count(v)) return curve;
  return std::nullopt;
}

// The model's parts: faces joined through the curves they share, each part's faces ascending, the
// parts in the order of their first face.
std::vector<std::vector<int>> parts_of(const cad::Model& model) {
  std::vector<int> root(model.num_surfaces());
  for (int s = 0; s < model.num_surfaces(); ++s) root[s] = s;
  auto find = [&](int s) {
    while (root[s] != s) s = root[s] = root[root[s]];
    return s;
  };
  for (int c = 0; c < model.num_curves(); ++c) {
    const std::vector<cad::SurfaceUse>& uses = model.surfaces_of_curve(c);
    for (std::size_t k = 1; k < uses.size(); ++k) root[find(uses[k].surface)] = find(uses[0].surface);
  }
  std::map<int, std::vector<int>> by_root;
  for (int s = 0; s < model.num_surfaces(); ++s) by_root[find(s)].push_back(s);
  std::vector<std::vector<int>> parts;
  for (auto& [r, faces] : by_root) parts.push_back(std::move(faces));
  std::sort(parts.begin(), parts.end());
  return parts;
}

// A part's bounding box, from its curves and a grid over each face.
cad::BBox part_box(const cad::Model& model, const std::vector<int>& faces) {
  cad::BBox box;
  for (int s : faces)
    for (const Vec3& p : face_samples(model, s)) box.add(p);
  return box;
}

// Whether two boxes share a box thicker than `margin` along every axis: parts inside one another
// in part (a wing sunk into a fuselage), not merely touching along a face (a tip cap left unsewn).
bool overlap(const cad::BBox& a, const cad::BBox& b, double margin) {
  return ((a.hi.cwiseMin(b.hi) - a.lo.cwiseMax(b.lo)).array() > margin).all();
}

// "[surface 0 ('fuselage'), surface 3 ('wing') and 4 more, within (x0, y0, z0) .. (x1, y1, z1)]".
std::string part_label(const cad::Model& model, const std::vector<int>& faces, const cad::BBox& box) {
  constexpr std::size_t kNamed = 3;
  std::vector<int> named(faces.begin(), faces.begin() + std::min(faces.size(), kNamed));
  std::string text = labels(model, named);
  if (faces.size() > kNamed) text += fmt::format(" and {} more", faces.size() - kNamed);
  return fmt::format("[{}, within ({:.6g}, {:.6g}, {:.6g}) .. ({:.6g}, {:.6g}, {:.6g})]", text, box.lo.x(), box.lo.y(),
                     box.lo.z(), box.hi.x(), box.hi.y(), box.hi.z());
}

int find_wall(const cad::Model& model) {
  std::vector<int> walls;
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (holds_a_body(model, s)) walls.push_back(s);
  if (walls.empty()) refuse_overlapping_parts(model);
  if (walls.empty()) refuse_seam_through_root(model);
  if (walls.empty())
    fail("no face holds a body's root loop as an inner loop: the model has no wall the body stands on "
         "(name the wall with geometry.wall, or check that the body is sewn to it: cad-info lists each curve's faces; "
         "a file holding the body only gets its wall and far field from geometry.wall_plane and geometry.farfield "
         "= {box | sphere | box_chords})");
  if (walls.size() > 1)
    fail("several faces hold a body's root loop (" + labels(model, walls) + "): name the wall with geometry.wall");
  return walls.front();
}

// The wall under the body's root: the root points' centroid projected on the wall's surface. It
// lies in the root's hole, outside the trimmed face, so the projection starts from a root point's
// parameters (an unguided one prefers points inside the face: the far side of a fuselage).
struct WallAtRoot {
  Vec3 point, normal;  ///< normal into the fluid: on a curved wall, the span direction
  Vec2 uv;
};

WallAtRoot wall_at_root(const cad::Surface& wall, const std::vector<Vec3>& root_points) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : root_points) centroid += p;
  const Vec2 start = wall.project(root_points.front()).uv;
  const cad::SurfaceProjection foot = wall.project(centroid / static_cast<double>(root_points.size()), start);
  return {foot.point, wall.normal(foot.uv), foot.uv};
}

// How far a point near the root lies behind the wall: minus its distance to the wall's untrimmed
// surface along the normal into the fluid (> 0 behind it). Newton from the root's foot finds the
// surface point under the body, not one on the far side.
double depth_below(const cad::Surface& wall, const WallAtRoot& root, const Vec3& x) {
  const cad::SurfaceProjection p = wall.project(x, root.uv);
  return -(x - p.point).dot(wall.normal(p.uv));
}

struct Extent {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double x) { lo = std::min(lo, x); hi = std::max(hi, x); }
  double length() const { return hi - lo; }
};

Extent extent(const std::vector<Vec3>& points, const Vec3& direction, const Vec3& origin) {
  Extent e;
  for (const Vec3& p : points) e.add((p - origin).dot(direction));
  return e;
}

}  // namespace

// The faces as geometry.join entries: ["#0", "#1", "#2"].
std::string join_entries(const std::vector<int>& faces) {
  std::string text;
  for (int s : faces) text += fmt::format("{}\"#{}\"", text.empty() ? "" : ", ", s);
  return "[" + text + "]";
}

std::optional<OverlappingParts> find_overlapping_parts(const cad::Model& model) {
  const std::vector<std::vector<int>> parts = parts_of(model);
  if (parts.size() < 2) return std::nullopt;
  std::vector<cad::BBox> boxes;
  for (const std::vector<int>& part : parts) boxes.push_back(part_box(model, part));
  const double margin = 1e-3 * model.bbox().diagonal();
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size(); ++j)
      if (overlap(boxes[i], boxes[j], margin)) {
        // The smaller part is the body (a wing in a fuselage, a blade on a hub).
        const std::size_t body = boxes[i].diagonal() < boxes[j].diagonal() ? i : j, wall = i + j - body;
        return OverlappingParts{parts[body], parts[wall], boxes[body], boxes[wall], static_cast<int>(parts.size())};
      }
  return std::nullopt;
}

void refuse_overlapping_parts(const cad::Model& model) {
  const std::optional<OverlappingParts> pair = find_overlapping_parts(model);
  if (!pair) return;
  const std::string why =
      "a body must share its root curves with the wall it stands on. An assembly of overlapping parts (a wing "
      "reaching into a fuselage or a hub, as OpenVSP and other design tools export) is joined at load when its "
      "parts are named: ";
  const std::string rest =
      " with geometry.farfield = {box = [...]} crossing the wall part's ends (the faces are the file's, as "
      "`semimesh cad-info FILE` lists them); or unite the parts in a CAD tool. Parts meant to touch that do not "
      "(faces left unsewn) need geometry.sew_tolerance above their gap";
  if (pair->count == 2)
    fail(fmt::format("the model falls apart into 2 parts that share no curve, and they overlap: {} and {}; {}"
                     "geometry.join = {{body = {}, wall = {}}}{}",
                     part_label(model, pair->body, pair->body_box), part_label(model, pair->wall, pair->wall_box), why,
                     join_entries(pair->body), join_entries(pair->wall), rest));
  // More parts (the other wing, the tails, a fairing): which to join is the user's choice.
  constexpr std::size_t kListed = 8;
  const std::vector<std::vector<int>> parts = parts_of(model);
  std::string list;
  for (std::size_t k = 0; k < std::min(parts.size(), kListed); ++k)
    list += (k ? ", " : "") + part_label(model, parts[k], part_box(model, parts[k]));
  if (parts.size() > kListed) list += fmt::format(" and {} more", parts.size() - kListed);
  fail(fmt::format("the model falls apart into {} parts that share no curve, some of which overlap: {}; {}"
                   "geometry.join = {{body = [one wing's faces], wall = [the fuselage's faces]}}, e.g. for the first "
                   "overlapping pair found {{body = {}, wall = {}}}, every other face left out,{}",
                   parts.size(), list, why, join_entries(pair->body), join_entries(pair->wall), rest));
}

void refuse_seam_through_root(const cad::Model& model) {
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (const std::optional<int> seam = seam_through_root(model, s))
      fail(fmt::format("{} looks like the wall a body stands on, but its seam, {}, runs into the body's root: "
                       "the root loop is joined to the face's outer boundary instead of being a hole in it; "
                       "export the wall (a fuselage, a hub) with its seam away from the body (e.g. at its "
                       "bottom), or split it there",
                       cad::surface_label(model, s), cad::curve_label(model, *seam)));
}

bool has_wall_with_root_loop(const cad::Model& model) {
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (holds_a_body(model, s)) return true;
  return false;
}

CadRoles detect_cad_roles(const cad::Model& model, std::optional<int> wall) {
  CadRoles roles;
  if (wall) {
    if (*wall < 0 || *wall >= model.num_surfaces()) fail(fmt::format("no surface {}", *wall));
  }
  roles.wall = wall ? *wall : find_wall(model);
  const std::set<int> root = root_curves(model, roles.wall);
  if (root.empty())
    fail("the wall " + cad::surface_label(model, roles.wall) +
         " has no inner loop another face shares: no body stands on it (name the body with geometry.body)");
  roles.body = faces_behind(model, roles.wall, root);
  // One body: the faces reached from one root curve are all of them (two wings on one wall, or a
  // file holding two bodies, reach two sets).
  if (const std::vector<int> first = faces_behind(model, roles.wall, {*root.begin()}); first.size() < roles.body.size()) {
    std::vector<int> other;
    std::set_difference(roles.body.begin(), roles.body.end(), first.begin(), first.end(), std::back_inserter(other));
    fail(fmt::format("the wall {} holds more than one body: {}, and apart from it {}; semimesh meshes one body on one "
                     "wall (remove the others from the file, or split it)",
                     cad::surface_label(model, roles.wall), labels(model, first), labels(model, other)));
  }
  if (std::none_of(roles.body.begin(), roles.body.end(), [&](int s) { return !model.surface(s).is_planar(); }))
    fail("the body " + labels(model, roles.body) +
         " has no curved face: it is no streamlined body (a file holding a box and no wing?); semimesh meshes "
         "around a wing, blade or fin");
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (s != roles.wall && !std::binary_search(roles.body.begin(), roles.body.end(), s)) roles.farfield.push_back(s);
  if (roles.farfield.empty())
    fail("every face other than the wall " + cad::surface_label(model, roles.wall) +
         " belongs to the body: the model has no far field (an outer shell)");

  std::vector<Vec3> root_points;
  for (int c : root) {
    const auto points = curve_samples(model.curve(c));
    root_points.insert(root_points.end(), points.begin(), points.end());
  }
  const WallAtRoot foot = wall_at_root(model.surface(roles.wall), root_points);
  const Vec3& normal = foot.normal;
  const Vec3& origin = foot.point;
  roles.span_direction = normal;
  const Vec3 x_axis = Vec3::UnitX();
  const Vec3 streamwise_raw = x_axis - x_axis.dot(normal) * normal;
  if (streamwise_raw.norm() < 1e-6)
    fail("the wall " + cad::surface_label(model, roles.wall) + " is normal to x: the streamwise direction (x) lies along the span");
  const Vec3 streamwise = streamwise_raw.normalized();

  const double tolerance = 1e-6 * std::max(1.0, model.bbox().diagonal());
  Extent span;
  std::vector<std::vector<Vec3>> samples(model.num_surfaces());
  for (int s : roles.body) {
    samples[s] = face_samples(model, s);
    const Extent e = extent(samples[s], normal, origin);
    double deepest = 0.0;
    for (const Vec3& p : samples[s]) deepest = std::max(deepest, depth_below(model.surface(roles.wall), foot, p));
    if (deepest > std::max(tolerance, 1e-6 * e.length()))
      fail("the body " + cad::surface_label(model, s) + " reaches " + fmt::format("{:.6g}", deepest) +
           " below the wall " + cad::surface_label(model, roles.wall));
    span.add(e.hi);
  }
  roles.span = span.hi;

  const Extent chord = extent(root_points, streamwise, origin);
  roles.chord = chord.length();

  // The base: narrow on the root, at its downstream end; the most downstream one if several.
  double best = -std::numeric_limits<double>::infinity();
  for (int s : roles.body) {
    double length = 0.0;
    Extent along;
    for (int c : root) {
      bool used = false;
      for (const cad::SurfaceUse& u : model.surfaces_of_curve(c)) used = used || u.surface == s;
      if (!used) continue;
      length += model.curve(c).length();
      const Extent e = extent(curve_samples(model.curve(c)), streamwise, origin);
      along.add(e.lo);
      along.add(e.hi);
    }
    const double middle = 0.5 * (along.lo + along.hi);
    if (length > 0.0 && length < kNarrowFraction * roles.chord && along.length() < kAcrossFraction * length &&
        middle > chord.hi - kDownstreamFraction * roles.chord && middle > best) {
      best = middle;
      roles.te_base = s;
    }
  }

  for (int s : roles.body) {
    if (s == roles.te_base || uses_any(model, s, root)) continue;
    const Extent across = extent(samples[s], normal, origin);
    const Extent along = extent(samples[s], streamwise, origin);
    if (across.hi >= roles.span - 1e-3 * roles.span && across.length() < kFlatTipFraction * along.length())
      roles.tip.push_back(s);
  }
  return roles;
}

std::string describe_cad_roles(const cad::Model& model, const CadRoles& roles) {
  const Vec3& n = roles.span_direction;
  std::string text;
  text += "wall      " + cad::surface_label(model, roles.wall) + "\n";
  text += "body      " + labels(model, roles.body) + "\n";
  text += "te_base   " + (roles.te_base ? cad::surface_label(model, *roles.te_base) : std::string("none (a closed trailing edge)")) + "\n";
  text += "tip       " + labels(model, roles.tip) + "\n";
  text += "far field " + labels(model, roles.farfield) + "\n";
  text += fmt::format("span      {:.6g} along ({:.4g}, {:.4g}, {:.4g}) (the wall's normal); root chord {:.6g}\n", roles.span,
                      n.x(), n.y(), n.z(), roles.chord);
  return text;
}

}  // namespace semimesh::surface
