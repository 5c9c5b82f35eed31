// The run configuration: a TOML file (docs/config.md documents every key) read into the stages'
// own params structs. Defaults run the paper's case: a NACA 0012 wing of chord 1 with a blunt
// trailing edge on a wall, far field about 10 chords away, order 4, N = 5 layers of ratio r = 2.
//
// Each key is declared once, as a row of its struct's table (semimesh/params/table.hpp): the
// stages' tables (shell_keys, size_keys, far_field_keys, curving_keys, layer_keys) and the
// pipeline's own below. Its default is the struct's member initialiser. Adding a key is one row
// (and its doc line in docs/config.md, which a test compares with the tables).
//
// Unknown keys, wrong types and out-of-range values are errors naming the key, its value, what was
// expected and where it was written (file:line, or the --set option).
#pragma once

#include "semimesh/error.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/surface/size_field.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace semimesh::pipeline {

class ConfigError : public InputError {
 public:
  using InputError::InputError;
};

/// [geometry.naca]: the analytic wing (backends "naca" and "occ" without a source file).
struct NacaConfig {
  std::string code = "0012";
  double chord = 1.0;
  double span = 3.0;
  double taper = 1.0;
  double sweep = 0.0;         ///< degrees
  std::string te = "blunt";   ///< "blunt" | "sharp"
  std::array<double, 6> box = {-10, -10, 0, 11, 10, 10};  ///< xmin, ymin, zmin, xmax, ymax, zmax
};

/// [geometry]: where the CAD model comes from and which surfaces play which role.
struct GeometryConfig {
  std::string backend = "naca";  ///< registry name: "naca", "occ", "vendor"
  std::string source;            ///< CAD file, resolved against the config file's folder; empty: generator
  std::string units = "chord";   ///< label of the model's unit
  double scale = 1.0;            ///< factor applied to a CAD file's coordinates at load
  NacaConfig naca;
  std::vector<std::string> body = {"upper", "lower", "te_base", "tip"};  ///< te_base dropped by default for a sharp TE
  std::string wall = "wall";
  std::vector<std::string> farfield = {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"};
};

/// [nearfield]: the partition (topology) and the one-layer shell around the body.
struct NearFieldConfig {
  std::string topology = "O";  ///< "O" (implemented), "C", "H" (rejected for now)
  nearfield::ShellParams shell;
};

/// [boundary_layer]: splitting of the near-field elements into N layers.
struct BoundaryLayerConfig {
  ho::LayerDistribution split;              ///< layers, ratio
  std::optional<double> first_cell_height;  ///< instead of ratio: height of the first layer
  /// Optional: the ratio varies linearly along the segment A -> B = ratio_line (xa, ya, za, xb, yb,
  /// zb): the ratio (or the one from first_cell_height) at A, ratio_end at B, by the projection of
  /// each body vertex onto the segment, constant beyond its ends. Both keys or neither.
  std::optional<std::array<double, 6>> ratio_line;
  std::optional<double> ratio_end;
};

/// [sizing]: the surface size field, and counts prescribed on the NACA wing's named curves.
struct SizingConfig {
  surface::SizeParams size;
  int chordwise = 0;  ///< segments on each root/tip section curve; 0: from the size field
  int spanwise = 0;   ///< segments on each spanwise edge; 0: from the size field
};

/// [checks]
struct ChecksConfig {
  /// An element whose certified scaled Jacobian is below this counts as invalid: a positive floor
  /// keeps numerically degenerate elements (det J ~ 1e-16 of its maximum) out of a written mesh.
  double min_scaled_jacobian = 1e-5;
};

/// [output]
struct OutputConfig {
  std::vector<std::string> formats = {"msh41", "vtu"};  ///< names from output_formats()
  std::string directory = ".";   ///< resolved against the current directory
  std::string basename = "mesh";
  bool allow_invalid = false;    ///< write the mesh even when a check fails
};

struct Config {
  GeometryConfig geometry;
  NearFieldConfig nearfield;
  BoundaryLayerConfig boundary_layer;
  SizingConfig sizing;
  farfield::FarFieldParams farfield;
  ho::CurvingParams highorder;
  ChecksConfig checks;
  OutputConfig output;
};

/// A [section] of the file: its dotted name and its keys (rows into Config).
struct ConfigSection {
  std::string name;
  params::Table<Config> keys;
};

/// Every section and key, in file order (the source of reading, checking and the docs test).
const std::vector<ConfigSection>& config_sections();

/// Parses TOML text. `source_name` names the text in messages (a file name); relative geometry
/// sources are resolved against `base_directory` (empty: left as written). `overrides` are
/// "dotted.key=value" strings, value in TOML syntax (strings may omit their quotes), applied over
/// the text before validation. Throws ConfigError.
Config parse_config(const std::string& text, const std::string& source_name, const std::string& base_directory = {},
                    const std::vector<std::string>& overrides = {});

/// Reads and parses a file (see parse_config). Throws ConfigError when it cannot be read.
Config load_config(const std::string& path, const std::vector<std::string>& overrides = {});

/// Ratio of the boundary layer: `ratio`, or the r solving h1 (r^N - 1) / (r - 1) = thickness when
/// first_cell_height h1 is given.
double effective_layer_ratio(const BoundaryLayerConfig& layer, double thickness);

}  // namespace semimesh::pipeline
