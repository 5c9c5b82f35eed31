#include "semimesh/pipeline/pipeline.hpp"

#include "semimesh/backends/builtin.hpp"
#include "semimesh/cad/labels.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/curving/follow_exposed_body.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/repair.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/output_set.hpp"
#include "semimesh/mesh/compact.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/nearfield/h_shell.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/pipeline/closed_model.hpp"
#include "semimesh/pipeline/output_formats.hpp"
#include "semimesh/pipeline/pictures.hpp"
#include "semimesh/pipeline/pyfr_limits.hpp"
#include "semimesh/ho/splitting/precut_faces.hpp"
#include "semimesh/ho/splitting/pyramid_columns.hpp"
#include "semimesh/pipeline/report.hpp"
#include "semimesh/pipeline/roles.hpp"
#include "semimesh/pipeline/split_stacks.hpp"
#include "semimesh/pipeline/weld_nodes.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "semimesh/surface/shell_size_limit.hpp"

#include "conformity_beside.hpp"

#include <fmt/format.h>

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>  // malloc_trim
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>

namespace semimesh::pipeline {
namespace {

// Samples per boundary-face edge for the geometric error: enough to see the largest deviation of
// an order-8 face, cheap next to the curving itself.
constexpr int kGeometricErrorSamples = 6;
// Bound on |curved body volume - triangulated body volume| / triangulated body volume.
constexpr double kCurvedBodyVolumeFraction = 0.02;
// Nodes closer than this (relative to the chord) are one node after the H-type split: the split and
// the pre-cut skin compute the same points up to round-off.
constexpr double kWeldTolerance = 1e-9;
// A fan's cut node this close to the curved face (times the chord) stays: far inside the weld's reach.
constexpr double kPrecutTolerance = 1e-12;
// Subdivisions of the repair stage's certification.
constexpr int kRepairDepth = 8;

// The stage's progress callback: forwards to `progress`, never letting the fraction go back (the
// parts of a stage report at their own start; a part may end below where the next starts).
ProgressCallback stage_progress(Progress& progress) {
  auto last = std::make_shared<double>(0.0);
  return [&progress, last](double fraction, const std::string& step) {
    *last = std::max(*last, std::clamp(fraction, 0.0, 1.0));
    progress.stage_progress(*last, step);
  };
}

// The C library keeps what a stage freed (the hash tables' nodes, a replaced mesh's small blocks) for
// later allocations, resident: given back to the system before each stage, the peak is what the
// stages hold, not what they once held.
void release_freed_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

// Runs one stage: reports its start and end, and turns its exceptions into RunError. A body that
// takes a ProgressCallback reports its progress through it.
template <typename Stage>
auto stage(const std::string& name, Progress& progress, RunResult& result, Stage&& body) {
  progress.stage_started(name);
  release_freed_memory();
  const ProgressCallback report = stage_progress(progress);
  auto call = [&] {
    if constexpr (std::is_invocable_v<Stage&, const ProgressCallback&>)
      return body(report);
    else
      return body();
  };
  const auto start = std::chrono::steady_clock::now();
  auto finish = [&] {
    const StageTiming timing{name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    result.stages.push_back(timing);
    progress.stage_finished(timing);
  };
  auto fail = [&](Error::Cause cause, const std::string& what) -> RunError {
    // Stage errors that already name their stage (e.g. "near field: ...") are not prefixed twice.
    const std::string prefix = name + ": ";
    return RunError(cause, name, what.rfind(prefix, 0) == 0 ? what : prefix + what);
  };
  try {
    if constexpr (std::is_void_v<decltype(call())>) {
      call();
      finish();
    } else {
      auto value = call();
      finish();
      return value;
    }
  } catch (const RunError&) {
    throw;
  } catch (const Error& e) {
    throw fail(e.cause(), e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw fail(Error::Cause::BadInput, e.what());  // the output folder cannot be made or written
  } catch (const std::exception& e) {
    throw fail(Error::Cause::Internal, e.what());
  }
}

std::string box_text(const std::array<double, 6>& b) {
  return fmt::format("{},{},{},{},{},{}", b[0], b[1], b[2], b[3], b[4], b[5]);
}

std::string numbers_text(const double* x, std::size_t n) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) text += fmt::format("{}{}", i ? "," : "", x[i]);
  return text;
}

// The generated wing's box for geometry.farfield = {box | box_chords} (it stands on z = 0, checked
// by the config): the box cut at the wall, or k chords around the wing's bounding box.
std::array<double, 6> generated_box(const GeometryConfig& g) {
  const FarFieldShapeConfig& f = g.farfield_shape;
  if (f.box) {
    std::array<double, 6> box = *f.box;
    box[2] = 0.0;
    return box;
  }
  const NacaConfig& w = g.naca;
  const double c = w.chord, shift = w.span * std::tan(w.sweep * M_PI / 180.0), margin = *f.box_chords * c;
  const double x_lo = std::min(0.0, shift), x_hi = std::max(c, shift + w.taper * c);
  return {x_lo - margin, -0.5 * c - margin, 0.0, x_hi + margin, 0.5 * c + margin, w.span + margin};
}

// A list as one parameter, an entry per line.
std::string lines_text(const std::vector<std::string>& entries) {
  std::string text;
  for (const std::string& e : entries) text += e + "\n";
  return text;
}

// geometry.wall_plane or geometry.join, and geometry.farfield = {...}, as the occ backend's parameters.
void set_domain_params(const GeometryConfig& g, cad::Params& params) {
  const FarFieldShapeConfig& f = g.farfield_shape;
  if (g.join.given()) {
    params.set("occ.join_body", lines_text(g.join.body.value_or(std::vector<std::string>{})));
    params.set("occ.join_wall", lines_text(g.join.wall.value_or(std::vector<std::string>{})));
  } else {
    std::array<double, 6> plane{};
    std::copy(g.wall_plane.point->begin(), g.wall_plane.point->end(), plane.begin());
    std::copy(g.wall_plane.normal->begin(), g.wall_plane.normal->end(), plane.begin() + 3);
    params.set("occ.wall_plane", numbers_text(plane.data(), 6));
  }
  if (f.box) params.set("occ.farfield_box", numbers_text(f.box->data(), 6));
  if (g.body_cut.given()) {
    std::array<double, 6> cut{};
    std::copy(g.body_cut.point->begin(), g.body_cut.point->end(), cut.begin());
    std::copy(g.body_cut.normal->begin(), g.body_cut.normal->end(), cut.begin() + 3);
    params.set("occ.body_cut", numbers_text(cut.data(), 6));
  }
  if (f.box_chords) params.set("occ.farfield_box_chords", fmt::format("{}", *f.box_chords));
  if (f.sphere.centre) {
    const std::array<double, 4> sphere{(*f.sphere.centre)[0], (*f.sphere.centre)[1], (*f.sphere.centre)[2], *f.sphere.radius};
    params.set("occ.farfield_sphere", numbers_text(sphere.data(), 4));
  }
}

}  // namespace

cad::Source cad_source(const GeometryConfig& g) {
  cad::Source source;
  source.path = g.source;
  const bool generated = g.source.empty() && (g.backend == "naca" || g.backend == "occ");
  if (generated) {
    source.params.set("naca.code", g.naca.code);
    source.params.set("naca.chord", fmt::format("{}", g.naca.chord));
    source.params.set("naca.span", fmt::format("{}", g.naca.span));
    source.params.set("naca.taper", fmt::format("{}", g.naca.taper));
    source.params.set("naca.sweep", fmt::format("{}", g.naca.sweep));
    if (g.naca.dihedral != 0.0) source.params.set("naca.dihedral", fmt::format("{}", g.naca.dihedral));
    source.params.set("naca.te", g.naca.te);
    if (g.naca.tip != "flat") source.params.set("naca.tip", g.naca.tip);
    if (g.naca.wall != "plane") source.params.set("naca.wall", g.naca.wall);
    if (g.naca.wall_radius) source.params.set("naca.wall_radius", fmt::format("{}", *g.naca.wall_radius));
    if (g.naca.wall_angle) source.params.set("naca.wall_angle", fmt::format("{}", *g.naca.wall_angle));
    // On a fuselage a box left at the plane's default gives way to the backend's, around the fuselage.
    if (g.naca.wall == "plane" || g.naca.box != NacaConfig{}.box)
      source.params.set("naca.box", box_text(g.wall_plane.given() ? generated_box(g) : g.naca.box));
    if (g.units != "auto") source.params.set("naca.units", g.units);
    if (g.scale != 1.0)
      throw ConfigError("config error: geometry.scale = " + fmt::format("{}", g.scale) +
                        ": expected 1 for a generated wing (scale applies to CAD files; set naca.chord instead)");
  } else if (g.backend == "occ") {
    source.params.set("occ.scale", fmt::format("{}", g.scale));
    if (g.units != "auto") source.params.set("occ.units", g.units);
    if (g.sew_tolerance) source.params.set("occ.sew_tolerance", fmt::format("{}", *g.sew_tolerance));
    if (g.wall_plane.given() || g.join.given()) set_domain_params(g, source.params);
  } else if (g.wall_plane.given()) {
    throw ConfigError("config error: geometry.wall_plane: backend '" + g.backend +
                      "' cannot build a wall and a far field around a body-only file (backend \"occ\" can)");
  }
  return source;
}

namespace {

// The wake's keys with te_base naming the resolved base (the near field finds it by name); left
// as written when none was found (a sharp trailing edge), for the near field's own message.
nearfield::WakeParams wake_with_base(const cad::Model& model, nearfield::WakeParams wake, const Roles& roles) {
  if (!roles.te_base) return wake;
  const std::string& name = model.surface(*roles.te_base).name();
  if (model.find_surface(name) != roles.te_base)
    throw ConfigError(fmt::format("config error: wake.te_base: the trailing-edge base {} shares its name with {}: give "
                                  "the CAD faces distinct names",
                                  cad::surface_label(model, *roles.te_base),
                                  cad::surface_label(model, *model.find_surface(name))));
  wake.te_base = name;
  return wake;
}

// The wake's keys as the near field takes them: te_base resolved; for PyFR the rear interfaces
// made translational (PyFR's pyramid rule; a different mesh, so only when asked for).
nearfield::WakeParams wake_for(const Config& config, const cad::Model& model, const Roles& roles) {
  nearfield::WakeParams wake = wake_with_base(model, config.wake, roles);
  wake.translational_rear_interfaces = config.output.target == OutputTarget::Pyfr;
  wake.to_outlet = config.output.target == OutputTarget::Pyfr;
  wake.outlet_cell = config.farfield.box_size;
  return wake;
}

// The trailing-edge base's faces the H-type near field sweeps (the root's base and the faces going on
// with it to the tip: nearfield::detail::trailing_edge_base); a named face off the body alone (the
// near field refuses it).
std::vector<int> te_base_faces(const cad::Model& model, const Roles& roles) {
  if (!std::count(roles.body.begin(), roles.body.end(), *roles.te_base)) return {*roles.te_base};
  return nearfield::detail::trailing_edge_base(model, {roles.body, roles.wall}, *roles.te_base);
}

// Prescribed counts on the named section (chordwise) and spanwise curves of NACA wing models.
surface::ModelMeshOptions mesh_options(const cad::Model& model, const Config& config, const Roles& roles) {
  const SizingConfig& s = config.sizing;
  surface::ModelMeshOptions options;
  // H-type: the trailing-edge base's faces as structured quads, swept into the wake block.
  if (roles.te_base)
    for (int s : te_base_faces(model, roles)) options.structured_surfaces.insert(s);
  auto prescribe = [&](int segments, const char* key, std::initializer_list<const char*> names) {
    if (segments == 0) return;
    int found = 0;
    for (int c = 0; c < model.num_curves(); ++c)
      for (const char* name : names)
        if (model.curve(c).name() == name) {
          options.curve_counts[c] = surface::CurveCount{segments, {}};
          ++found;
        }
    if (found == 0)
      throw ConfigError(fmt::format("config error: {} = {}: the CAD model has no curves named {} (only NACA wing "
                                    "models name them; set 0 to size them from the size field)",
                                    key, segments, fmt::join(names, ", ")));
  };
  // Cosine bunching clusters the chordwise nodes at the leading and trailing edges.
  prescribe(s.chordwise, "sizing.chordwise", {"root_upper", "root_lower", "tip_upper", "tip_lower"});
  for (auto& [curve, count] : options.curve_counts) count.bunching.law = surface::Bunching::Law::Cosine;
  prescribe(s.spanwise, "sizing.spanwise", {"leading_edge", "te_upper", "te_lower", "trailing_edge"});
  return options;
}

// boundary_layer.ratio_line / ratio_end: the ratio linear along A -> B (projection, clamped), from
// `ratio_at_a` at A to ratio_end at B; no field (the uniform ratio) without them.
// (wall_layer's alike.)
ho::RatioField ratio_field(const std::optional<std::array<double, 6>>& line, const std::optional<double>& end,
                           double ratio_at_a) {
  if (!line || !end) return {};
  const std::array<double, 6>& l = *line;
  const Eigen::Vector3d a(l[0], l[1], l[2]), ab = Eigen::Vector3d(l[3], l[4], l[5]) - a;
  const double ratio_at_b = *end;
  return [a, ab, ratio_at_a, ratio_at_b](const Eigen::Vector3d& x) {
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return ratio_at_a + t * (ratio_at_b - ratio_at_a);
  };
}

// H-type: the wing's ratio (`upstream`, or the constant `ratio`) up to the trailing edge, then
// linear with the distance downstream to `ratio_end` at the wake's far end (paper, section 4).
double wake_ratio(const nearfield::WakeBlock& wake, const ho::RatioField& upstream, double ratio, double ratio_end,
                  const Eigen::Vector3d& x) {
  const double at_te = upstream ? upstream(x) : ratio;
  return at_te + nearfield::wake_fraction(wake, x) * (ratio_end - at_te);
}

ho::RatioField wake_ratio_field(const nearfield::WakeBlock& wake, const ho::RatioField& upstream, double ratio,
                                double ratio_end) {
  return [wake, upstream, ratio, ratio_end](const Eigen::Vector3d& x) {
    return wake_ratio(wake, upstream, ratio, ratio_end, x);
  };
}

// Largest (longest body-side edge / mean vertical edge) over the first-layer prisms of the wing.
double max_first_layer_aspect(const mesh::Mesh& split, const std::vector<nearfield::LayerStack>& stacks,
                              const std::vector<std::size_t>& first_layer) {
  double worst = 0.0;
  for (std::size_t k = 0; k < stacks.size(); ++k) {
    const mesh::Element& e = split.elements()[first_layer[k]];
    if (e.shape != ho::Shape::Prism || stacks[k].directions.front().family != nearfield::LayerFamily::Wing) continue;
    auto x = [&](int v) -> const Eigen::Vector3d& { return split.node(e.vertices[v]); };
    const double longest = std::max({(x(1) - x(0)).norm(), (x(2) - x(1)).norm(), (x(0) - x(2)).norm()});
    const double height = ((x(3) - x(0)).norm() + (x(4) - x(1)).norm() + (x(5) - x(2)).norm()) / 3.0;
    worst = std::max(worst, longest / height);
  }
  return worst;
}

// The chord for a generated wing; otherwise the streamwise (x) extent of the body's surface nodes.
double reference_length(const GeometryConfig& g, const std::vector<const surface::SurfaceMesh*>& body) {
  if (g.source.empty() && (g.backend == "naca" || g.backend == "occ")) return g.naca.chord;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const surface::SurfaceMesh* s : body)
    for (const Eigen::Vector3d& p : s->points) {
      lo = std::min(lo, p.x());
      hi = std::max(hi, p.x());
    }
  return hi > lo ? hi - lo : 1.0;
}

// The largest resident size of this process's own memory: VmHWM of /proc/self/status. Not
// getrusage's ru_maxrss, which Linux carries over an exec from the process that forked it (a run
// started by a Python script holding 500 MB reported 500 MB).
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kilobytes
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

}  // namespace

double RunResult::total_seconds() const {
  double total = 0.0;
  for (const StageTiming& s : stages) total += s.seconds;
  return total;
}

std::vector<std::string> output_paths(const OutputConfig& output) {
  const std::filesystem::path dir(output.directory);
  std::vector<std::string> paths;
  for (const std::string& f : output.formats) {
    const OutputFormat& format = output_format(f);
    const bool shared = std::any_of(output.formats.begin(), output.formats.end(), [&](const std::string& g) {
      return g != f && output_format(g).extension == format.extension;
    });
    const std::string& extension = shared && !format.extension_when_shared.empty() ? format.extension_when_shared
                                                                                  : format.extension;
    paths.push_back((dir / (output.basename + extension)).string());
  }
  paths.push_back((dir / "report.json").string());
  return paths;
}

namespace {

// The CAD model and the surfaces that play each role.
struct Geometry {
  std::unique_ptr<cad::Model> model;
  Roles roles;
};

Geometry load_geometry(const Config& config, Progress& progress, RunResult& result) {
  const cad::Registry registry = backends::default_registry();
  Geometry g;
  g.model = stage("load CAD", progress, result, [&] {
    auto model = registry.load(config.geometry.backend, cad_source(config.geometry));
    require_closed(*model, config.geometry.sew_tolerance);
    return model;
  });
  result.model_repairs = g.model->repairs();
  g.roles = stage("roles", progress, result, [&] { return resolve_roles(*g.model, config); });
  return g;
}

surface::SurfaceMeshes mesh_surfaces(const Config& config, const Geometry& g, Progress& progress, RunResult& result) {
  const cad::Model& model = *g.model;
  const surface::SizeField size = stage("size field", progress, result, [&](const ProgressCallback& report) {
    surface::SizeParams params = config.sizing.size;
    // Curved body faces under a straight outer face: the shell's thickness bounds the body's edges.
    // Progress: the shell limits (most of the time when they run), then the curvature sampling.
    if (config.highorder.order > 1) {
      const auto limits = surface::shell_size_sources(model, {config.nearfield.shell.thickness, g.roles.body}, params,
                                                      progress_part(report, 0.0, 0.9));
      params.point_sources.insert(params.point_sources.end(), limits.begin(), limits.end());
    }
    if (report) report(config.highorder.order > 1 ? 0.9 : 0.0, "curvature");
    surface::SizeField field(model, params);
    if (report) report(1.0, "curvature");
    return field;
  });
  for (const std::string& w : surface::size_warnings(config.sizing.size)) result.warnings.push_back("size field: " + w);
  surface::SurfaceMeshes surfaces = stage("surface mesh", progress, result, [&](const ProgressCallback& report) {
    return surface::mesh_model_surfaces(model, size, mesh_options(model, config, g.roles), report);
  });
  result.surface_triangles = surfaces.num_triangles();
  result.surface_quads = surfaces.num_quads();
  return surfaces;
}

struct LinearMesh {
  mesh::Mesh mesh;
  std::vector<nearfield::LayerStack> stacks;  ///< every layer element, with its direction(s)
  nearfield::WakeBlock wake;                  ///< H-type: the wake block (no hexes otherwise)
  std::vector<ho::PrecutFace> precut_faces;   ///< H-type: the fan's cuts on the junction hexes' faces
  ho::CurvedAhead curved_ahead;                   ///< order > 1: what was curved beside TetGen (may be empty)
  std::vector<ho::InheritedBounds> certified_ahead;  ///< and certified there (the repair's depth and floor)
  ho::PieceBoundsAhead pieces_ahead;  ///< and the split pieces' inherited bounds derived there
};

// The wing layer's ratio and its field along the body (from boundary_layer, y+ resolved).
struct WingRatio {
  double ratio = 1.0;
  ho::RatioField upstream;
};

WingRatio wing_ratio(const Config& config, double chord) {
  const BoundaryLayerConfig layer = resolve_y_plus(config.boundary_layer, chord);
  const double ratio = effective_layer_ratio(layer, config.nearfield.shell.thickness);
  return {ratio, ratio_field(config.boundary_layer.ratio_line, config.boundary_layer.ratio_end, ratio)};
}

// The wing layer's split interfaces along a layer edge from x, as the split will place them (its
// reference interfaces mapped to [0, 1]); none when the layer is not split.
nearfield::LayerFractions layer_fractions(const Config& config, double chord) {
  const int layers = config.boundary_layer.split.layers;
  if (layers <= 1) return {};
  const WingRatio wing = wing_ratio(config, chord);
  const double ratio_end = config.wake.ratio_end;
  return [=](const Eigen::Vector3d& x, const nearfield::WakeBlock& wake) {
    std::vector<double> f = ho::layer_interfaces(layers, wake_ratio(wake, wing.upstream, wing.ratio, ratio_end, x));
    for (double& z : f) z = 0.5 * (z + 1.0);
    return f;
  };
}

// The two layer families the split takes: the wing's (on an H-type its ratio field decays along
// the wake) and the wall's, at the configured numbers of layers (the wall's 1 without a junction).
struct LayerFamilies {
  FamilySplit wing, wall;
};

LayerFamilies layer_families(const Config& config, double chord, const nearfield::WakeBlock& wake) {
  const int layers = config.boundary_layer.split.layers;
  const int wall_layers = builds_junction(config) ? config.wall_layer.split.layers : 1;
  const WingRatio wing = wing_ratio(config, chord);
  const double wall_ratio = wall_layers > 1 ? effective_wall_ratio(config.wall_layer) : 1.0;
  ho::RatioField wing_field = wing.upstream;
  if (wake.hexes > 0) wing_field = wake_ratio_field(wake, wing.upstream, wing.ratio, config.wake.ratio_end);
  return {{ho::LayerDistribution{layers, wing.ratio}, wing_field},
          {ho::LayerDistribution{wall_layers, wall_ratio},
           ratio_field(config.wall_layer.ratio_line, config.wall_layer.ratio_end, wall_ratio)}};
}

// The linear mesh: the near-field shell (O: prisms; C: prisms and the root junction's hexes; H: and
// the wake block's hexes), then the far field around it (C, H: with the wall layer), and the layer
// stacks of the whole mesh.
LinearMesh build_linear_mesh(const Config& config, const Geometry& g, const surface::SurfaceMeshes& surfaces,
                             double chord, Progress& progress, RunResult& result) {
  const bool junction = builds_junction(config);
  nearfield::NearField near = stage("near field", progress, result, [&] {
    const nearfield::BodyRoles roles{g.roles.body, g.roles.wall};
    if (junction && config.nearfield.topology == "H")
      return nearfield::build_h_shell(*g.model, surfaces, roles, config.nearfield.shell, config.nearfield.junction,
                                      config.wall_layer.thickness, wake_for(config, *g.model, g.roles),
                                      g.model->bbox(),
                                      layer_fractions(config, chord));
    return junction ? nearfield::build_c_shell(*g.model, surfaces, roles, config.nearfield.shell,
                                               config.nearfield.junction, config.wall_layer.thickness)
                    : nearfield::build_o_shell(*g.model, surfaces, roles, config.nearfield.shell);
  });
  result.junction_hexes = near.junction_hexes;
  result.wake.hexes = near.wake.hexes;
  result.wake.length = near.wake.reach;
  result.wake.streamwise_cells = near.wake.streamwise_cells;
  result.wake.gap = near.wake.gap;
  nearfield::WakeBlock wake = near.wake;
  std::vector<ho::PrecutFace> precut_faces = near.precut_faces;
  result.thickness_min = near.thickness_min;
  result.thickness_max = near.thickness_max;
  for (const nearfield::Warning& w : near.warnings)
    result.warnings.push_back(fmt::format("near field: {} at ({:.4g}, {:.4g}, {:.4g})", w.message, w.where.x(),
                                          w.where.y(), w.where.z()));
  // While TetGen's process makes the far field (a core idle otherwise), the elements made so far
  // are curved and certified as the curve and repair stages will, and their split pieces' bounds
  // derived as the split will: the curving takes the nodes placed for the same edges, faces and
  // elements (ho::CurvedAhead), the repair the bounds of the elements whose nodes are then the same
  // (fingerprints), the split the pieces' bounds of the elements whose nodes and pieces are then
  // the same; each computes the rest itself. Stopped when TetGen answers: whatever was not done
  // ahead is done by the stages, as without it.
  ho::CurvedAhead curved_ahead;
  std::vector<ho::InheritedBounds> certified_ahead;
  ho::PieceBoundsAhead pieces_ahead;
  const bool splits = config.boundary_layer.split.layers > 1 ||
                      (junction && config.wall_layer.split.layers > 1);
  farfield::BesideTetgen beside;
  if (config.highorder.order > 1)
    beside = [&](const mesh::Mesh& so_far, const std::vector<nearfield::LayerStack>& stacks,
                 const std::atomic<bool>& stop) {
      curved_ahead = ho::curve_ahead(so_far, *g.model, config.highorder, stop);
      if (curved_ahead.empty()) return;
      certified_ahead = ho::certify_ahead(curved_ahead.curved, kRepairDepth, config.checks.min_scaled_jacobian, stop);
      if (splits && config.checks.inherit_bounds && !stop) {
        const LayerFamilies families = layer_families(config, chord, wake);
        pieces_ahead = piece_bounds_ahead(curved_ahead.curved, stacks, families.wing, families.wall, stop);
      }
    };
  farfield::FarField far = stage("far field", progress, result, [&](const ProgressCallback& report) {
    return farfield::build_far_field(*g.model, std::move(near), config.farfield, g.roles.farfield, g.roles.wall,
                                     junction ? config.wall_layer.thickness : 0.0, report, beside);
  });
  result.far_field = far.stats;
  return {std::move(far.mesh),     std::move(far.stacks),      std::move(wake), std::move(precut_faces),
          std::move(curved_ahead), std::move(certified_ahead), std::move(pieces_ahead)};
}

// Order P: nodes on the CAD (the far field and the skin stay straight-sided), then the repair of
// what curving folded. What cannot be repaired stays invalid and is reported by the checks (exit 2).
// `curved_ahead`, `certified_ahead`: what was curved and certified beside TetGen (build_linear_mesh),
// taken where it holds; the curved mesh is dropped once the curving has taken its nodes.
mesh::Mesh raise_order(const Config& config, const cad::Model& model, const mesh::Mesh& linear,
                       ho::CurvedAhead& curved_ahead, const std::vector<ho::InheritedBounds>& certified_ahead,
                       Progress& progress, RunResult& result) {
  mesh::Mesh curved = stage("curve", progress, result, [&](const ProgressCallback& report) {
    mesh::Mesh on_cad = ho::curve_mesh(linear, model, config.highorder, &result.curving, report, &curved_ahead);
    curved_ahead = ho::CurvedAhead();
    // A sharp trailing edge's bare triangles at its tip end: the far field there bends with them.
    ho::follow_exposed_body(on_cad, "wing", "farfield");
    return on_cad;
  });
  result.node_placement = config.highorder.placement == ho::NodePlacement::Springs ? "springs" : "parameter";
  if (result.curving.optimisation_fallbacks > 0)
    result.warnings.push_back(fmt::format("curve: the spring optimisation did not converge on {} edge(s)/face(s) "
                                          "within {} iterations; they keep their parameter-space positions",
                                          result.curving.optimisation_fallbacks, config.highorder.spring_iterations));
  return stage("repair", progress, result, [&](const ProgressCallback& report) {
    const double floor = config.checks.min_scaled_jacobian;
    // Certifying every element is the bulk of the stage; repairing the few invalid ones the rest.
    const ho::MeshValidity validity =
        ho::certify_mesh(curved, kRepairDepth, floor, progress_part(report, 0.0, 0.9), &certified_ahead);
    if (validity.all_valid()) return std::move(curved);
    ho::Repaired repaired = ho::repair_invalid(curved, model, validity.invalid_elements, floor);
    const ho::RepairStats& stats = repaired.stats;
    result.warnings.push_back(fmt::format("curving made {} element(s) invalid; repaired {}, {} could not be repaired",
                                          validity.invalid,
                                          stats.repaired_interior + stats.repaired_free_nodes + stats.repaired_body_following,
                                          stats.failures.size()));
    constexpr std::size_t kReasonsShown = 10;
    for (std::size_t i = 0; i < std::min(kReasonsShown, stats.failures.size()); ++i)
      result.warnings.push_back("repair: " + stats.failures[i].reason);
    return std::move(repaired.mesh);
  });
}

// The elements with no entry in `inherited` (ascending) other than tetrahedra (the far field's,
// straight-sided: certified about as fast as they are fingerprinted), ascending.
std::vector<std::size_t> curved_without_bounds(const mesh::Mesh& mesh, const std::vector<ho::InheritedBounds>& inherited) {
  std::vector<std::size_t> wanted;
  auto entry = inherited.begin();
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    while (entry != inherited.end() && entry->element < e) ++entry;
    if (entry != inherited.end() && entry->element == e) continue;
    if (mesh.elements()[e].shape != ho::Shape::Tetrahedron) wanted.push_back(e);
  }
  return wanted;
}

// Two lists of bounds of distinct elements, each ascending, as one ascending list.
std::vector<ho::InheritedBounds> merged_bounds(std::vector<ho::InheritedBounds> a, std::vector<ho::InheritedBounds> b) {
  if (b.empty()) return a;
  std::vector<ho::InheritedBounds> out;
  out.reserve(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out),
             [](const ho::InheritedBounds& x, const ho::InheritedBounds& y) { return x.element < y.element; });
  return out;
}

// Splitting after curving, every layer stack in one pass along its own direction(s): the pieces
// inherit the coarse elements' curved map (isoparametric).
mesh::Mesh split(const Config& config, mesh::Mesh coarse, LinearMesh& linear, double chord,
                 Progress& progress, RunResult& result, std::vector<ho::InheritedBounds>& inherited) {
  const std::vector<nearfield::LayerStack>& stacks = linear.stacks;
  const int layers = result.layers.layers, wall_layers = result.wall_layers.layers;
  const BoundaryLayerConfig layer = resolve_y_plus(config.boundary_layer, chord);
  const LayerFamilies families = layer_families(config, chord, linear.wake);
  const double ratio = families.wing.distribution.ratio;
  if (linear.wake.hexes > 0) {
    result.wake.ratio_first = ratio;
    result.wake.ratio_last = config.wake.ratio_end;
  }
  // H-type: the far field stands on skin quads cut like the split; the weld makes their nodes the split's.
  const bool weld = linear.wake.hexes > 0 && layers > 1;
  StackSplit split = stage("split", progress, result, [&](const ProgressCallback& report) {
    StackSplit fine = split_stacks(std::move(coarse), stacks, families.wing, families.wall, report,
                                   config.checks.inherit_bounds, ho::SplitEntities::Adopted, &linear.pieces_ahead);
    // The coarse elements' inner nodes and the entities only they used are no longer used by
    // any element: drop them, and number the entities as an element by element build would (the
    // weld does both in its own renumbering of the mesh).
    if (!weld) fine.mesh = mesh::without_unreferenced_nodes(std::move(fine.mesh));
    return fine;
  });
  coarse = mesh::Mesh();  // not needed any more
  linear.pieces_ahead = ho::PieceBoundsAhead();  // served the split: not held through the weld
  const std::size_t split_elements = split.mesh.elements().size();
  std::vector<ho::InheritedBounds> certified_behind;  // beside the weld's rebuild, for the checks
  if (weld)
    split.mesh = stage("weld", progress, result, [&](const ProgressCallback& report) {
      // Where the weld rebuilds the entities (on one thread), the other core certifies behind that
      // rebuild the elements the split gave no bounds (the wake's pieces, the curved unsplit ones)
      // as the checks will; the checks take those whose nodes are then still the same
      // (fingerprints). A remap (the usual case) publishes the elements only at its end: the
      // checks then certify them, on every core.
      const std::vector<std::size_t> wanted = curved_without_bounds(split.mesh, split.inherited);
      const double floor = config.checks.min_scaled_jacobian;
      // Depth 0: the checks take only bounds decided by the first expansion (certify_mesh), which
      // are the same at any depth; an element that needs more is left to them.
      const BesideRebuild certify = [&](const mesh::Mesh& being_rebuilt, const std::atomic<std::size_t>& rebuilt,
                                        const std::atomic<bool>& stop) {
        certified_behind = ho::certify_behind(being_rebuilt, wanted, rebuilt, 0, floor, stop);
      };
      mesh::Mesh welded = weld_coincident_nodes(std::move(split.mesh), kWeldTolerance * chord, report, certify).mesh;
      // The weld re-extends the far field next to the pre-cut rims harmonically: bend it with the
      // bare triangles again (follow_exposed_body in raise_order moved its vertices already).
      ho::follow_exposed_body(welded, "wing", "farfield", /*moved_before=*/true);
      return welded;
    });
  // The weld keeps the elements in order (the bounds' element indices hold); an element it moved
  // no longer matches its fingerprint.
  inherited = merged_bounds(std::move(split.inherited), std::move(certified_behind));
  if (split.mesh.elements().size() != split_elements) inherited.clear();
  if (layers > 1) {
    result.layers.requested_ratio = ratio;
    result.layers.requested_ratio_end = config.boundary_layer.ratio_end.value_or(ratio);
    result.layers.achieved_ratio = split.wing.achieved_ratio;
    result.layers.first_cell_height_min = split.wing.first_cell_height_min;
    result.layers.first_cell_height_max = split.wing.first_cell_height_max;
    result.layers.max_first_layer_aspect = max_first_layer_aspect(split.mesh, stacks, split.first_layer);
    if (layer.y_plus) {
      const double length = layer.reference_length.value_or(chord);
      result.layers.first_cell_height_target = *layer.first_cell_height;
      result.layers.y_plus_min = y_plus_of_height(split.wing.first_cell_height_min, *layer.reynolds, length);
      result.layers.y_plus_max = y_plus_of_height(split.wing.first_cell_height_max, *layer.reynolds, length);
    }
  }
  if (wall_layers > 1) {
    result.wall_layers.requested_ratio = families.wall.distribution.ratio;
    result.wall_layers.requested_ratio_end = config.wall_layer.ratio_end.value_or(families.wall.distribution.ratio);
    result.wall_layers.achieved_ratio = split.wall.achieved_ratio;
    result.wall_layers.first_cell_height_min = split.wall.first_cell_height_min;
    result.wall_layers.first_cell_height_max = split.wall.first_cell_height_max;
  }
  return std::move(split.mesh);
}

// output.target = "pyfr": no pyramid on a base that is not a parallelogram, PyFR's importer rule
// (the H-type's transition pyramids on the wake block's trapezoids): the hex columns under them are
// split into prisms and their end pyramids into tetrahedra. Before the checks, which certify the pieces.
// The mesh is taken by value and moved on: a mesh without refused pyramids is not copied.
mesh::Mesh meet_pyfr_pyramid_rule(mesh::Mesh mesh, Progress& progress, RunResult& result) {
  return stage("pyfr", progress, result, [&] {
    try {
      // A tenth of PyFR's tolerance: a margin for its own order of operations on the same doubles.
      ho::PyramidColumns split = ho::split_pyramid_columns(std::move(mesh), kPyfrParallelogramTolerance / 10);
      result.pyfr_columns = split.stats;
      return std::move(split.mesh);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("output.target = \"pyfr\" cannot be met: ") + e.what() +
                       "; for PyFR use nearfield.topology = \"C\" (no pyramids; docs/solvers.md says which H-type "
                       "pyramids cannot be split yet)");
    }
  });
}

// The chord: geometry.naca.chord for a generated wing, else the body's streamwise extent.
double chord_of(const Config& config, const Geometry& g, const surface::SurfaceMeshes& surfaces) {
  std::vector<const surface::SurfaceMesh*> body;
  for (int s : g.roles.body) body.push_back(&surfaces.surfaces[s]);
  return reference_length(config.geometry, body);
}

// Twice the centroid's distance to the wall times the area, summed over flat facets with corners on
// a curved wall: a bound on the volume between them and the wall (a parabolic bulge's mean height
// is two thirds of its largest, and the centroid sits near the largest).
double facet_gap(const cad::Surface& wall, const cad::Vec3& a, const cad::Vec3& b, const cad::Vec3& c) {
  const cad::Vec3 centroid = (a + b + c) / 3.0;
  return 2.0 * (0.5 * (b - a).cross(c - a).norm()) * wall.project(centroid).distance;
}

// How far the element volume of a mesh on a curved wall may be from the surface meshes' box minus
// body: both stand on flat facets under the wall (the surface stage's and the far field's own), each
// missing the volume between its facets and the wall.
double curved_wall_volume_gap(const cad::Surface& wall, const surface::SurfaceMesh& wall_mesh, const mesh::Mesh& mesh) {
  double gap = 0.0;
  for (const auto& t : wall_mesh.triangles)
    gap += facet_gap(wall, wall_mesh.points[t[0]], wall_mesh.points[t[1]], wall_mesh.points[t[2]]);
  const auto it = std::find(mesh.group_names().begin(), mesh.group_names().end(), "wall");
  const auto group = static_cast<std::uint16_t>(it - mesh.group_names().begin());
  for (const mesh::BoundaryFace& f : mesh.boundary_faces()) {
    if (f.group != group) continue;
    gap += facet_gap(wall, mesh.node(f.vertices[0]), mesh.node(f.vertices[1]), mesh.node(f.vertices[2]));
    if (f.shape == ho::Shape::Quadrilateral)
      gap += facet_gap(wall, mesh.node(f.vertices[0]), mesh.node(f.vertices[2]), mesh.node(f.vertices[3]));
  }
  return gap;
}

// The element volume against box minus body (result.volume, result.expected_volume_tolerance).
// `known`: the elements' integrals the certification found (checks::ValidityResult::integrals).
void check_mesh_volume(const Geometry& g, const surface::SurfaceMeshes& surfaces, const std::vector<double>& known,
                       RunResult& result) {
  std::vector<const surface::SurfaceMesh*> body, box;
  for (int s : g.roles.body) body.push_back(&surfaces.surfaces[s]);
  for (int s : g.roles.farfield) box.push_back(&surfaces.surfaces[s]);
  const bool curved_far_field = std::any_of(g.roles.farfield.begin(), g.roles.farfield.end(),
                                            [&](int s) { return !g.model->surface(s).is_planar(); });
  // A curved far field (a sphere) is triangulated by the far-field stage at its own sizes, and
  // where nodes lie on its CAD curved at order > 1: the box it bounds is the mesh's own far-field
  // faces', not the surface stage's triangulation's (equal to round-off on planar faces only).
  if (curved_far_field) box.clear();
  const cad::Surface& wall = g.model->surface(g.roles.wall);
  const surface::SurfaceMesh& wall_mesh = surfaces.surfaces[g.roles.wall];
  result.volume = wall.is_planar() ? checks::check_volume(result.mesh, body, box, wall_mesh, &known)
                                   : checks::check_volume_curved_wall(result.mesh, body, box, wall_mesh, &known);
  // A curved body bulges out of its triangulation by O(h^2) of its size: the element volume may
  // then differ from box - (triangulated) body by a small fraction of the body, not by round-off.
  double gap = 0.0;
  if (result.mesh.order() > 1) gap += kCurvedBodyVolumeFraction * std::abs(result.volume.body_volume);
  if (!wall.is_planar()) gap += curved_wall_volume_gap(wall, wall_mesh, result.mesh);
  if (gap > 0) result.expected_volume_tolerance = gap / result.volume.expected_volume();
}

void check(const Config& config, const Geometry& g, const surface::SurfaceMeshes& surfaces, double chord,
           const std::vector<ho::InheritedBounds>& inherited, Progress& progress, RunResult& result) {
  stage("checks", progress, result, [&](const ProgressCallback& report) {
    // The geometric error is a serial pass that only reads the mesh, the certification a parallel
    // loop: they run side by side, each filling its own figures, so that no serial pass leaves a
    // core idle at the end. The volume comes after the certification: it takes the integrals the
    // certification found (affine elements, trilinear hexahedra, split pieces) instead of gathering
    // those elements' nodes again (the same figures, in less time). The conformity check runs
    // beside this stage and the write (ConformityBeside, run()).
    if (report) report(0.0, "volume and certification");
    std::future<void> geometric = std::async(std::launch::async, [&] {
      std::vector<int> curved = g.roles.body;  // the far field stays straight-sided (a sphere's too)
      curved.push_back(g.roles.wall);
      const ho::GeometricError error =
          ho::geometric_error(result.mesh, *g.model, chord, kGeometricErrorSamples, curved);
      result.geometric_error = GeometricErrorFigures{chord, error.max_rel, error.rms_rel, error.samples};
    });
    std::exception_ptr validity_error, geometric_error;
    try {
      result.validity = checks::check_validity(result.mesh, 100, config.checks.min_scaled_jacobian,
                                               progress_part(report, 0.0, 0.9), &inherited);
      if (report) report(0.9, "volume");
      check_mesh_volume(g, surfaces, result.validity.integrals, result);
      result.validity.integrals = {};  // served the volume
    } catch (...) {
      validity_error = std::current_exception();
    }
    try {
      geometric.get();
    } catch (...) {
      geometric_error = std::current_exception();
    }
    if (validity_error) std::rethrow_exception(validity_error);
    if (geometric_error) std::rethrow_exception(geometric_error);
  });
  for (const mesh::Element& e : result.mesh.elements()) {
    ++result.elements_by_type[ho::to_string(e.shape)];
    ++result.elements_by_region[result.mesh.region_names()[e.region]];
  }
  for (const mesh::BoundaryFace& f : result.mesh.boundary_faces())
    ++result.boundary_faces_by_group[result.mesh.group_names()[f.group]];
}


}  // namespace

namespace {

/// The mesh files, one thread per format (their bytes do not depend on it): the node positions are
/// resampled once for all, in the mesh itself (a copy would be the run's largest array: 24 bytes a
/// node), and moved back when the files are written or one failed (io::EquispacedNodes: the
/// element interiors from a copy of theirs, the rest to round-off). What each writer
/// wrote is added to `written` in config order, also when another format failed (its first error,
/// in config order, is rethrown). Progress: the mean of the files' own fractions, reported under a
/// lock (one call at a time).
void write_mesh_files(mesh::Mesh& mesh, const std::vector<std::string>& formats,
                      const std::vector<std::string>& paths, MeshAfterWrite after_write,
                      const ProgressCallback& report, std::vector<std::string>& written,
                      const std::function<void()>& before_restore) {
  if (formats.empty()) return before_restore();
  io::EquispacedNodes nodes(mesh, io::EquispacedNodes::InPlace{});
  if (after_write == MeshAfterWrite::AsWritten) nodes.leave_resampled();
  std::mutex lock;
  std::vector<double> done(formats.size(), 0.0);
  auto file_progress = [&](std::size_t i) -> ProgressCallback {
    if (!report) return {};
    return [&, i, file = std::filesystem::path(paths[i]).filename().string()](double f, const std::string& step) {
      const std::lock_guard<std::mutex> guard(lock);
      done[i] = std::max(done[i], f);
      double sum = 0;
      for (double d : done) sum += d;
      report(sum / static_cast<double>(done.size()), step.empty() ? file : file + ": " + step);
    };
  };
  std::vector<std::future<std::vector<std::string>>> writers;
  for (std::size_t i = 0; i < formats.size(); ++i)
    writers.push_back(std::async(std::launch::async, [&, i] {
      return output_format(formats[i]).write(mesh, nodes, paths[i], file_progress(i));
    }));
  std::exception_ptr first_error;
  for (auto& writer : writers) {
    try {
      for (const std::string& path : writer.get()) written.push_back(path);
    } catch (...) {
      if (!first_error) first_error = std::current_exception();
    }
  }
  try {  // also after a writer's error: what runs beside must end before the positions move back
    before_restore();
  } catch (...) {
    if (!first_error) first_error = std::current_exception();
  }
  if (first_error) std::rethrow_exception(first_error);
}

// write_outputs, with `conformity` (when given) joined into result.conformity once the mesh files
// are staged: they are committed only when every check then passes or output.allow_invalid is on.
void write_outputs_beside(const Config& config, Progress& progress, RunResult& result, MeshAfterWrite after_write,
                          ConformityBeside* conformity) {
  stage("write", progress, result, [&](const ProgressCallback& report) {
    const std::vector<std::string> paths = output_paths(config.output);
    // Progress: an equal part per mesh file, and one for the pictures and the report.
    const double parts = static_cast<double>(config.output.formats.size() + 1);
    try {
      std::filesystem::create_directories(config.output.directory);
      // Every file goes to a staging folder first and all replace an earlier run's files together
      // at the end: when one fails, the output folder is left exactly as it was.
      io::OutputSet outputs(config.output.directory);
      const auto staged = [&](const std::string& path) {
        return outputs.staged(std::filesystem::path(path).filename().string());
      };
      std::vector<std::string> staged_paths;
      for (const std::string& path : paths) staged_paths.push_back(staged(path));
      // The pictures from the mesh as made, before the writers resample its nodes.
      if (report && config.output.pictures) report(0.0, "pictures");
      const std::vector<Picture> pictures =
          config.output.pictures ? mesh_pictures(result.mesh, result.validity, config.output.picture_station)
                                 : std::vector<Picture>{};
      std::vector<std::string> staged_files;
      const ProgressCallback files_progress = progress_part(report, 0.0, (parts - 1) / parts);
      write_mesh_files(result.mesh, config.output.formats, staged_paths, after_write, files_progress, staged_files, [&] {
        if (!conformity) return;
        if (files_progress) files_progress(1.0, "conformity");
        result.conformity = conformity->join();
      });
      // The staging folder goes with `outputs`: the output folder stays as it was.
      if (!result.checks_passed() && !config.output.allow_invalid) return;
      for (const std::string& file : staged_files) result.written_files.push_back(outputs.final_path(file));
      if (report) report((parts - 1) / parts, "report.json");
      for (const Picture& picture : pictures) {
        const std::string name = config.output.basename + picture.suffix;
        io::AtomicFile file(outputs.staged(name));
        file.write(picture.svg);
        file.commit();
        result.written_files.push_back(outputs.final_path(name));
        result.pictures.push_back(outputs.final_path(name));
      }
      result.peak_memory_mb = peak_memory_mb();
      io::AtomicFile report_file(staged_paths.back());
      report_file.write(report_json(result, config));
      report_file.commit();
      outputs.commit();
      result.written_files.push_back(paths.back());
    } catch (...) {
      result.written_files.clear();
      result.pictures.clear();
      throw;
    }
  });
}

}  // namespace

void write_outputs(const Config& config, Progress& progress, RunResult& result, MeshAfterWrite after_write) {
  write_outputs_beside(config, progress, result, after_write, nullptr);
}

RunResult run(const Config& config, Progress& progress, MeshAfterWrite after_write) {
  RunResult result;
  const Geometry geometry = load_geometry(config, progress, result);
  const surface::SurfaceMeshes surfaces = mesh_surfaces(config, geometry, progress, result);
  const double chord = chord_of(config, geometry, surfaces);
  LinearMesh linear = build_linear_mesh(config, geometry, surfaces, chord, progress, result);
  result.mesh = std::move(linear.mesh);
  if (config.highorder.order > 1)
    result.mesh = raise_order(config, *geometry.model, result.mesh, linear.curved_ahead, linear.certified_ahead,
                              progress, result);
  result.layers.layers = config.boundary_layer.split.layers;
  result.wall_layers.layers = builds_junction(config) ? config.wall_layer.split.layers : 1;
  std::vector<ho::InheritedBounds> inherited;  // the split pieces' bounds, for the checks
  // A sharp trailing edge's fan: its cuts must be where the split puts the hexes' nodes on their
  // faces (curved at order P on a curved wall, on the chord at order 1), or the weld misses them.
  if (linear.wake.hexes > 0 && result.layers.layers > 1 && !linear.precut_faces.empty())
    ho::follow_precut_faces(result.mesh, linear.precut_faces, kPrecutTolerance * chord);
  if (result.layers.layers > 1 || result.wall_layers.layers > 1)
    result.mesh = split(config, std::move(result.mesh), linear, chord, progress, result, inherited);
  linear = LinearMesh();  // its layer stacks and cuts served the split
  if (config.output.target == OutputTarget::Pyfr) {
    result.mesh = meet_pyfr_pyramid_rule(std::move(result.mesh), progress, result);
    inherited = {};  // elements renumbered: every one is certified on its own
  }
  // From here the mesh changes no more but for its node positions (the writers' resampling).
  ConformityBeside conformity(result.mesh);
  check(config, geometry, surfaces, chord, inherited, progress, result);
  inherited = {};  // served the checks; the write needs the room
  // A user writing MSH for PyFR hears now what its importer would refuse.
  if (std::any_of(config.output.formats.begin(), config.output.formats.end(),
                  [](const std::string& f) { return f == "msh41-ascii" || f == "msh22"; }))
    for (const std::string& refusal : pyfr_refusals(result.mesh)) result.warnings.push_back("output: " + refusal);
  result.peak_memory_mb = peak_memory_mb();
  // The files are staged while the conformity check ends; written when it passes too.
  if ((result.validity.ok() && result.volume_ok()) || config.output.allow_invalid)
    write_outputs_beside(config, progress, result, after_write, &conformity);
  else
    result.conformity = conformity.join();
  return result;
}

}  // namespace semimesh::pipeline
