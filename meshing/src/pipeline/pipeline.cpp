#include "semimesh/pipeline/pipeline.hpp"

#include "semimesh/backends/builtin.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/repair.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/pipeline/report.hpp"
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "semimesh/surface/shell_size_limit.hpp"

#include <fmt/format.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <type_traits>

namespace semimesh::pipeline {
namespace {

// Samples per boundary-face edge for the geometric error: enough to see the largest deviation of
// an order-8 face, cheap next to the curving itself.
constexpr int kGeometricErrorSamples = 6;
// Bound on |curved body volume - triangulated body volume| / triangulated body volume.
constexpr double kCurvedBodyVolumeFraction = 0.02;

// Runs one stage: reports its start and end, and turns its exceptions into RunError.
template <typename Stage>
auto stage(const std::string& name, Progress& progress, RunResult& result, Stage&& body) {
  progress.stage_started(name);
  const auto start = std::chrono::steady_clock::now();
  auto finish = [&] {
    const StageTiming timing{name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    result.stages.push_back(timing);
    progress.stage_finished(timing);
  };
  auto fail = [&](RunError::Kind kind, const std::string& what) -> RunError {
    return RunError(kind, name, name + ": " + what);
  };
  try {
    if constexpr (std::is_void_v<decltype(body())>) {
      body();
      finish();
    } else {
      auto value = body();
      finish();
      return value;
    }
  } catch (const RunError&) {
    throw;
  } catch (const cad::CadError& e) {
    throw fail(e.kind() == cad::CadError::Kind::Geometry ? RunError::Kind::Internal : RunError::Kind::BadInput, e.what());
  } catch (const ConfigError& e) {
    throw fail(RunError::Kind::BadInput, e.what());
  } catch (const surface::SurfaceMeshError& e) {
    throw fail(RunError::Kind::BadInput, e.what());
  } catch (const nearfield::NearFieldError& e) {
    throw fail(RunError::Kind::BadInput, e.what());
  } catch (const farfield::FarFieldError& e) {
    throw fail(RunError::Kind::BadInput, e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw fail(RunError::Kind::BadInput, e.what());
  } catch (const std::exception& e) {
    throw fail(RunError::Kind::Internal, e.what());
  }
}

std::string box_text(const std::array<double, 6>& b) {
  return fmt::format("{},{},{},{},{},{}", b[0], b[1], b[2], b[3], b[4], b[5]);
}

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
    source.params.set("naca.te", g.naca.te);
    source.params.set("naca.box", box_text(g.naca.box));
    source.params.set("naca.units", g.units);
    if (g.scale != 1.0)
      throw ConfigError("config error: geometry.scale = " + fmt::format("{}", g.scale) +
                        ": expected 1 for a generated wing (scale applies to CAD files; set naca.chord instead)");
  } else if (g.backend == "occ") {
    source.params.set("occ.scale", fmt::format("{}", g.scale));
    source.params.set("occ.units", g.units);
  }
  return source;
}

int surface_id(const cad::Model& model, const std::string& key, const std::string& name) {
  if (auto id = model.find_surface(name)) return *id;
  std::string names;
  for (int s = 0; s < model.num_surfaces(); ++s) names += (s ? ", " : "") + model.surface(s).name();
  throw ConfigError("config error: " + key + ": the CAD model has no surface named '" + name + "' (its surfaces: " + names + ")");
}

struct Roles {
  std::vector<int> body, farfield;
  int wall = -1;
};

Roles resolve_roles(const cad::Model& model, const GeometryConfig& g) {
  Roles roles;
  for (const std::string& name : g.body) roles.body.push_back(surface_id(model, "geometry.body", name));
  for (const std::string& name : g.farfield) roles.farfield.push_back(surface_id(model, "geometry.farfield", name));
  roles.wall = surface_id(model, "geometry.wall", g.wall);
  return roles;
}

surface::SizeParams size_params(const SizingConfig& s) {
  surface::SizeParams p;
  p.max_size = s.max_size;
  p.min_size = s.min_size;
  p.curvature_segments = s.curvature_segments;
  p.gradation = s.gradation;
  p.le_size = s.le_size;
  p.te_size = s.te_size;
  return p;
}

// Prescribed counts on the named section (chordwise) and spanwise curves of NACA wing models.
surface::ModelMeshOptions mesh_options(const cad::Model& model, const SizingConfig& s) {
  surface::ModelMeshOptions options;
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

nearfield::ShellParams shell_params(const NearFieldConfig& n) {
  nearfield::ShellParams p;
  p.thickness = n.thickness;
  p.normal_smoothing_passes = n.smoothing_passes;
  p.min_thickness_fraction = n.min_thickness_fraction;
  p.reduction_factor = n.reduction_factor;
  p.gradation = n.gradation;
  return p;
}

farfield::FarFieldParams far_params(const FarFieldConfig& f) {
  farfield::FarFieldParams p;
  p.box_size = f.box_size;
  p.wall_size = f.wall_size;
  p.growth = f.growth;
  p.radius_edge_ratio = f.radius_edge_ratio;
  p.max_volume = f.max_volume;
  return p;
}

ho::CurvingParams curving_params(const HighOrderConfig& h) {
  ho::CurvingParams p;
  p.order = h.order;
  p.node_set = h.node_set == "gll" ? ho::NodeSet::GLL : ho::NodeSet::Equispaced;
  p.placement = h.node_placement == "springs" ? ho::NodePlacement::Springs : ho::NodePlacement::Parameter;
  p.spring_iterations = h.spring_iterations;
  return p;
}

// boundary_layer.ratio_line / ratio_end: the ratio linear along A -> B (projection, clamped), from
// `ratio_at_a` at A to ratio_end at B; no field (the uniform ratio) without them.
ho::RatioField ratio_field(const BoundaryLayerConfig& b, double ratio_at_a) {
  if (!b.ratio_line || !b.ratio_end) return {};
  const std::array<double, 6>& l = *b.ratio_line;
  const Eigen::Vector3d a(l[0], l[1], l[2]), ab = Eigen::Vector3d(l[3], l[4], l[5]) - a;
  const double ratio_at_b = *b.ratio_end;
  return [a, ab, ratio_at_a, ratio_at_b](const Eigen::Vector3d& x) {
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return ratio_at_a + t * (ratio_at_b - ratio_at_a);
  };
}

// The near-field shell is the mesh's prisms (the far field holds tets and pyramids only).
std::vector<std::size_t> shell_prisms(const mesh::Mesh& mesh) {
  std::vector<std::size_t> prisms;
  for (std::size_t e = 0; e < mesh.elements().size(); ++e)
    if (mesh.elements()[e].shape == ho::Shape::Prism) prisms.push_back(e);
  return prisms;
}

// Largest (longest body-side edge / mean vertical edge) over the first-layer prisms. split_layers
// replaces the k-th split prism (input index i) by `layers` elements from the body outwards, so its
// first-layer element is at i + k (layers - 1).
double max_first_layer_aspect(const mesh::Mesh& split, const std::vector<std::size_t>& prisms, int layers) {
  double worst = 0.0;
  for (std::size_t k = 0; k < prisms.size(); ++k) {
    const mesh::Element& e = split.elements()[prisms[k] + k * static_cast<std::size_t>(layers - 1)];
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

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

void write_mesh_file(const mesh::Mesh& mesh, const std::string& format, const std::string& path) {
  if (format == "msh41") io::write_msh(mesh, path, io::MshVersion::V41);
  if (format == "msh22") io::write_msh(mesh, path, io::MshVersion::V22);
  if (format == "vtu") io::write_vtu(mesh, path);
  if (format == "nektar") io::write_nektar_xml(mesh, path);
}

}  // namespace

double RunResult::total_seconds() const {
  double total = 0.0;
  for (const StageTiming& s : stages) total += s.seconds;
  return total;
}

std::vector<std::string> output_paths(const OutputConfig& output) {
  const std::filesystem::path dir(output.directory);
  const bool both_msh = std::count(output.formats.begin(), output.formats.end(), "msh41") &&
                        std::count(output.formats.begin(), output.formats.end(), "msh22");
  std::vector<std::string> paths;
  for (const std::string& f : output.formats) {
    std::string name = output.basename;
    if (f == "msh41") name += ".msh";
    if (f == "msh22") name += both_msh ? ".v22.msh" : ".msh";
    if (f == "vtu") name += ".vtu";
    if (f == "nektar") name += ".xml";
    paths.push_back((dir / name).string());
  }
  paths.push_back((dir / "report.json").string());
  return paths;
}

RunResult run(const Config& config, Progress& progress) {
  RunResult result;
  const cad::Registry registry = backends::default_registry();

  std::unique_ptr<cad::Model> model = stage("load CAD", progress, result, [&] {
    return registry.load(config.geometry.backend, cad_source(config.geometry));
  });
  const Roles roles = stage("roles", progress, result, [&] { return resolve_roles(*model, config.geometry); });

  const surface::SizeField size = stage("size field", progress, result, [&] {
    surface::SizeParams params = size_params(config.sizing);
    // Curved body faces under a straight outer face: the shell's thickness bounds the body's edges.
    if (config.highorder.order > 1) {
      const auto limits = surface::shell_size_sources(*model, {config.nearfield.thickness, roles.body}, params);
      params.point_sources.insert(params.point_sources.end(), limits.begin(), limits.end());
    }
    return surface::SizeField(*model, params);
  });
  const surface::SurfaceMeshes surfaces = stage("surface mesh", progress, result, [&] {
    return surface::mesh_model_surfaces(*model, size, mesh_options(*model, config.sizing));
  });
  result.surface_triangles = surfaces.num_triangles();
  result.surface_quads = surfaces.num_quads();

  nearfield::NearField near = stage("near field", progress, result, [&] {
    return nearfield::build_o_shell(*model, surfaces, nearfield::BodyRoles{roles.body, roles.wall},
                                    shell_params(config.nearfield));
  });
  result.thickness_min = near.thickness_min;
  result.thickness_max = near.thickness_max;
  for (const nearfield::Warning& w : near.warnings)
    result.warnings.push_back(fmt::format("near field: {} at ({:.4g}, {:.4g}, {:.4g})", w.message, w.where.x(),
                                          w.where.y(), w.where.z()));

  stage("far field", progress, result, [&] {
    farfield::build_far_field(*model, near, far_params(config.farfield), roles.farfield, roles.wall);
  });
  // The far field stays straight-sided and so does the skin: curving moves only nodes on the CAD.
  result.mesh = std::move(near.mesh);
  if (config.highorder.order > 1)
    result.mesh = stage("curve", progress, result, [&] {
      return ho::curve_mesh(result.mesh, *model, curving_params(config.highorder), &result.curving);
    });
  if (config.highorder.order > 1) result.node_placement = config.highorder.node_placement;
  if (result.curving.optimisation_fallbacks > 0)
    result.warnings.push_back(fmt::format("curve: the spring optimisation did not converge on {} edge(s)/face(s) "
                                          "within {} iterations; they keep their parameter-space positions",
                                          result.curving.optimisation_fallbacks, config.highorder.spring_iterations));
  // Curving can fold an element between its nodes; relax its free nodes until it is proven valid.
  // What cannot be repaired stays invalid and is reported by the checks (exit code 2).
  if (config.highorder.order > 1)
    stage("repair", progress, result, [&] {
      const double floor = config.checks.min_scaled_jacobian;
      const ho::MeshValidity validity = ho::certify_mesh(result.mesh, 8, floor);
      if (validity.all_valid()) return;
      const ho::RepairStats repair = ho::repair_invalid(result.mesh, *model, validity.invalid_elements, floor);
      result.warnings.push_back(fmt::format("curving made {} element(s) invalid; repaired {}, {} could not be repaired",
                                            validity.invalid,
                                            repair.repaired_interior + repair.repaired_free_nodes +
                                                repair.repaired_body_following,
                                            repair.failures.size()));
      constexpr std::size_t kReasonsShown = 10;
      for (std::size_t i = 0; i < std::min(kReasonsShown, repair.failures.size()); ++i)
        result.warnings.push_back("repair: " + repair.failures[i].reason);
    });

  // Splitting after curving: the sub-prisms inherit the coarse prisms' curved map (isoparametric).
  const int layers = config.boundary_layer.layers;
  result.layers.layers = layers;
  if (layers > 1) {
    const std::vector<std::size_t> prisms = shell_prisms(result.mesh);
    const double ratio = effective_layer_ratio(config.boundary_layer, config.nearfield.thickness);
    ho::SplitStats split{};
    result.mesh = stage("split", progress, result, [&] {
      return ho::split_layers(result.mesh, prisms, ho::LayerDistribution{layers, ratio},
                              ratio_field(config.boundary_layer, ratio), &split);
    });
    result.layers.requested_ratio = ratio;
    result.layers.requested_ratio_end = config.boundary_layer.ratio_end.value_or(ratio);
    result.layers.achieved_ratio = split.achieved_ratio;
    result.layers.first_cell_height_min = split.first_cell_height_min;
    result.layers.first_cell_height_max = split.first_cell_height_max;
    result.layers.max_first_layer_aspect = max_first_layer_aspect(result.mesh, prisms, layers);
  }

  stage("checks", progress, result, [&] {
    result.conformity = checks::check_conformity(result.mesh);
    std::vector<const surface::SurfaceMesh*> body, box;
    for (int s : roles.body) body.push_back(&surfaces.surfaces[s]);
    for (int s : roles.farfield) box.push_back(&surfaces.surfaces[s]);
    result.volume = checks::check_volume(result.mesh, body, box, surfaces.surfaces[roles.wall]);
    // A curved body bulges out of its triangulation by O(h^2) of its size: the element volume may
    // then differ from box - (triangulated) body by a small fraction of the body, not by round-off.
    if (result.mesh.order() > 1)
      result.expected_volume_tolerance =
          kCurvedBodyVolumeFraction * std::abs(result.volume.body_volume) / result.volume.expected_volume();
    result.validity = checks::check_validity(result.mesh, 0, 100, config.checks.min_scaled_jacobian);
    const double chord = reference_length(config.geometry, body);
    const ho::GeometricError error = ho::geometric_error(result.mesh, *model, chord, kGeometricErrorSamples);
    result.geometric_error = GeometricErrorFigures{chord, error.max_rel, error.rms_rel, error.samples};
  });
  for (std::size_t e = 0; e < result.mesh.elements().size(); ++e)
    ++result.elements_by_type[ho::to_string(result.mesh.elements()[e].shape)];
  for (const mesh::BoundaryFace& f : result.mesh.boundary_faces())
    ++result.boundary_faces_by_group[result.mesh.group_names()[f.group]];

  if (!result.checks_passed() && !config.output.allow_invalid) {
    result.peak_memory_mb = peak_memory_mb();
    return result;
  }

  stage("write", progress, result, [&] {
    const std::vector<std::string> paths = output_paths(config.output);
    try {
      std::filesystem::create_directories(config.output.directory);
      for (std::size_t i = 0; i < config.output.formats.size(); ++i) {
        write_mesh_file(result.mesh, config.output.formats[i], paths[i]);
        result.written_files.push_back(paths[i]);
      }
      result.peak_memory_mb = peak_memory_mb();
      io::AtomicFile report(paths.back());
      report.write(report_json(result, config));
      report.commit();
      result.written_files.push_back(paths.back());
    } catch (...) {
      // Leave no partial output: remove what this run wrote (older files of other runs stay).
      std::error_code ignored;
      for (const std::string& p : result.written_files) std::filesystem::remove(p, ignored);
      result.written_files.clear();
      throw;
    }
  });
  return result;
}

}  // namespace semimesh::pipeline
