// `semimesh run` as a library call: CAD -> size field -> surface meshes -> near-field shell ->
// far field -> curving (order > 1) -> splitting of the shell into layers -> checks -> files. Each stage is a function of the previous one's value; only loading
// the CAD model and writing the files touch the file system.
#pragma once

#include "semimesh/checks/conformity.hpp"
#include "semimesh/checks/validity.hpp"
#include "semimesh/checks/volume.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/splitting/pyramid_columns.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/cad/source.hpp"
#include "semimesh/pipeline/config.hpp"

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::pipeline {

/// A failure of the run: the stage's error (its cause: bad input such as the config, the CAD, a
/// thickness that cannot work, TetGen rejecting the boundary; or internal), with the stage named.
class RunError : public Error {
 public:
  RunError(Cause cause, std::string stage, const std::string& message)
      : Error(cause, message), stage_(std::move(stage)) {}
  const std::string& stage() const { return stage_; }

 private:
  std::string stage_;
};

struct StageTiming {
  std::string name;
  double seconds = 0.0;
};

/// Receives the start and end of every stage (the CLI prints a line per stage) and, inside the long
/// ones (size field, surface mesh, far field, curve, repair, split, checks, write), the fraction done: from one
/// thread at a time, throttled (a few hundred calls per stage at most), non-decreasing within a stage
/// from 0 to 1; `step` names the part running (see semimesh/progress.hpp).
class Progress {
 public:
  virtual ~Progress() = default;
  virtual void stage_started(const std::string& /*name*/) {}
  virtual void stage_progress(double /*fraction*/, const std::string& /*step*/) {}
  virtual void stage_finished(const StageTiming& /*timing*/) {}
};

/// The volume-check tolerances: the element volume must match the boundary flux to round-off and
/// the box-minus-body volume of the (linear) surface meshes closely.
constexpr double kBoundaryVolumeTolerance = 1e-9;
constexpr double kExpectedVolumeTolerance = 1e-6;

/// The boundary-layer split of the near-field prisms (ho::split_layers). Heights are straight
/// distances along the prisms' vertical edges; the aspect ratio of a first-layer prism is its
/// longest body-side edge over its mean vertical edge.
struct LayerFigures {
  int layers = 1;                      ///< N of the split (1: the shell was not split)
  double requested_ratio = 1.0;        ///< r used (boundary_layer.ratio or from first_cell_height)
  double requested_ratio_end = 1.0;    ///< r at the end of boundary_layer.ratio_line (= requested_ratio without)
  double achieved_ratio = 1.0;         ///< mean over the vertical edges (ho::SplitStats)
  double first_cell_height_min = 0.0;
  double first_cell_height_max = 0.0;
  double max_first_layer_aspect = 0.0;
  double first_cell_height_target = 0.0;  ///< from boundary_layer.y_plus (0: not targeted)
  double y_plus_min = 0.0;                ///< y+ of first_cell_height_min / _max at the configured Reynolds number
  double y_plus_max = 0.0;
};

/// Distance from the boundary faces to their CAD surfaces relative to reference_length (the
/// chord: geometry.naca.chord for a generated wing, else the streamwise extent of the body).
struct GeometricErrorFigures {
  double reference_length = 1.0;
  double max_rel = 0.0;
  double rms_rel = 0.0;
  int samples = 0;
};

struct RunResult {
  mesh::Mesh mesh{1};
  std::vector<StageTiming> stages;
  std::map<std::string, std::size_t> elements_by_type;  ///< "tetrahedron" -> count, ...
  std::map<std::string, std::size_t> elements_by_region;  ///< "wing_layer" -> count, ...
  int junction_hexes = 0;                 ///< C-type: hexes along the root before splitting
  /// H-type (hexes 0 otherwise): the wake block before splitting, its length and streamwise cells,
  /// the wing layers' ratio at the trailing edge and at the far end, the measured gap above the wall layer.
  struct WakeFigures {
    int hexes = 0, streamwise_cells = 0;
    double length = 0.0, ratio_first = 1.0, ratio_last = 1.0, gap = 0.0;
  } wake;
  std::map<std::string, std::size_t> boundary_faces_by_group;
  std::size_t surface_triangles = 0;
  std::size_t surface_quads = 0;
  double thickness_min = 0.0;
  double thickness_max = 0.0;
  checks::ConformityResult conformity;
  checks::VolumeCheck volume;
  checks::ValidityResult validity;
  LayerFigures layers;        ///< the wing's boundary layer
  LayerFigures wall_layers;   ///< the wall's (C-type; layers = 1 and zeros without a wall layer)
  std::string node_placement;  ///< highorder.node_placement used by the curve stage; empty at order 1
  ho::CurvingStats curving;    ///< zeros at order 1
  farfield::FarFieldStats far_field;
  ho::PyramidColumnStats pyfr_columns;  ///< output.target = "pyfr": what was split (zeros otherwise)
  GeometricErrorFigures geometric_error;
  /// Tolerance of the element volume against box - body of the linear surface meshes: round-off for
  /// a linear mesh; a curved body's volume differs from its triangulation's (see pipeline.cpp).
  double expected_volume_tolerance = kExpectedVolumeTolerance;
  std::vector<std::string> model_repairs;  ///< what the backend repaired or built at load (cad::Model::repairs)
  std::vector<std::string> warnings;       ///< near-field warnings and departures from the config
  std::vector<std::string> written_files;  ///< empty when the checks failed and allow_invalid is off
  std::vector<std::string> pictures;       ///< of written_files, the SVG pictures (output.pictures)
  double peak_memory_mb = 0.0;             ///< peak resident set size of the process (getrusage)

  bool volume_ok() const {
    return volume.mesh.boundary_relative_error() <= kBoundaryVolumeTolerance &&
           volume.expected_relative_error() <= expected_volume_tolerance;
  }
  bool checks_passed() const { return conformity.ok() && validity.ok() && volume_ok(); }
  double total_seconds() const;
};

/// What the run loads for `geometry`: the file or the generator's keys, the backend's parameters
/// (units, scale, sewing) and, for a body-only file, the wall plane and far field to build.
cad::Source cad_source(const GeometryConfig& geometry);

/// What RunResult::mesh holds once the mesh files are written, whose nodes are equispaced (the
/// writers resample the mesh's own nodes in place).
enum class MeshAfterWrite {
  AsMeshed,   ///< the mesh as made: its node set and CAD attachments (the resampling undone)
  AsWritten,  ///< the mesh as the files hold it: equispaced nodes, no CAD attachments, nothing
              ///< undone (~0.2 s less on the paper's case): for a caller that reads no position after
};

/// Runs every stage. Throws RunError (kinds as above). When a check fails the mesh is not written
/// (unless config.output.allow_invalid): the result says which check failed. Files are written
/// atomically, report.json last; if one fails, the files this run had already written are removed.
RunResult run(const Config& config, Progress& progress, MeshAfterWrite after_write = MeshAfterWrite::AsMeshed);

/// The write stage of run(): the mesh files in config order, then report.json, atomically; on a
/// failure the files this call wrote are removed and the error rethrown. Sets written_files. A
/// result whose checks failed (checks_passed()) is written only with config.output.allow_invalid:
/// else nothing is, and the output folder stays as it was (run() stages the files while its
/// conformity check ends, and drops them when that check fails).
void write_outputs(const Config& config, Progress& progress, RunResult& result,
                   MeshAfterWrite after_write = MeshAfterWrite::AsMeshed);

/// Output file paths the configuration asks for, mesh formats in config order, then report.json.
std::vector<std::string> output_paths(const OutputConfig& output);

}  // namespace semimesh::pipeline
