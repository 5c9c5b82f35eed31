// The run configuration: a TOML file (docs/config.md documents every key) read into typed structs.
// Defaults run the paper's case: a NACA 0012 wing of chord 1 with a blunt trailing edge on a wall,
// far field about 10 chords away, order 4, N = 5 layers of ratio r = 2 in the boundary layer.
//
// Unknown keys, wrong types and out-of-range values are errors naming the key, its value, what was
// expected and where it was written (file:line, or the --set option).
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::pipeline {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

/// [nearfield]: the one-layer shell around the body.
struct NearFieldConfig {
  std::string topology = "O";         ///< "O" (implemented), "C", "H" (rejected for now)
  double thickness = 0.1;             ///< shell thickness delta, model units
  int smoothing_passes = 10;          ///< Laplacian smoothing passes of the node normals
  double min_thickness_fraction = 0.1;  ///< local reduction may not go below this fraction of delta
  double reduction_factor = 0.7;      ///< thickness multiplier per local reduction round, in (0, 1)
  double gradation = 0.5;             ///< |delta_x - delta_y| <= gradation |x - y| after a reduction
};

/// [boundary_layer]: splitting of the shell into N layers (used by the high-order stage).
struct BoundaryLayerConfig {
  int layers = 5;                             ///< N >= 1
  double ratio = 2.0;                         ///< r >= 1, growth of consecutive layers
  std::optional<double> first_cell_height;    ///< instead of ratio: height of the first layer
  /// Optional: the ratio varies linearly along the segment A -> B = ratio_line (xa, ya, za, xb, yb,
  /// zb): `ratio` (or the one from first_cell_height) at A, ratio_end at B, by the projection of
  /// each body vertex onto the segment, constant beyond its ends. Both keys or neither.
  std::optional<std::array<double, 6>> ratio_line;
  std::optional<double> ratio_end;
};

/// [sizing]: the surface size field.
struct SizingConfig {
  double max_size = 2.0;
  double min_size = 0.005;
  double curvature_segments = 4.0;  ///< segments per radian of turning; 0 disables
  double gradation = 1.2;
  double le_size = 0.02;            ///< 0: no leading-edge source
  double te_size = 0.01;            ///< 0: no trailing-edge source
  int chordwise = 0;                ///< segments on each root/tip section curve; 0: from the size field
  int spanwise = 0;                 ///< segments on each spanwise edge; 0: from the size field
};

/// [farfield]: the TetGen region between the skin, the wall and the box.
struct FarFieldConfig {
  double box_size = 2.0;             ///< target edge length on the box faces
  double wall_size = 1.0;            ///< target edge length on the wall, far from the wing
  double growth = 1.2;               ///< size gradation from the skin outwards
  double radius_edge_ratio = 1.5;    ///< TetGen quality bound (-q), >= 1
  double max_volume = 0.0;           ///< TetGen volume bound (-a); 0: none
};

/// [highorder]
struct HighOrderConfig {
  int order = 4;                 ///< P in 1..8
  std::string node_set = "gll";  ///< "gll" | "equispaced"
  /// "parameter" (the CAD parametrisation's smooth node map, optimal geometric accuracy) |
  /// "springs" (the paper's spring optimisation); see docs/config.md and ho/curving/curve_mesh.hpp
  std::string node_placement = "parameter";
  int spring_iterations = 50;    ///< Gauss-Newton iterations per edge or face before a fallback
};

/// [checks]
struct ChecksConfig {
  /// An element whose certified scaled Jacobian is below this counts as invalid: a positive floor
  /// keeps numerically degenerate elements (det J ~ 1e-16 of its maximum) out of a written mesh.
  double min_scaled_jacobian = 1e-5;
};

/// [output]
struct OutputConfig {
  std::vector<std::string> formats = {"msh41", "vtu"};  ///< of "msh41", "msh22", "vtu", "nektar"
  std::string directory = ".";   ///< resolved against the current directory
  std::string basename = "mesh";
  bool allow_invalid = false;    ///< write the mesh even when a check fails
};

struct Config {
  GeometryConfig geometry;
  NearFieldConfig nearfield;
  BoundaryLayerConfig boundary_layer;
  SizingConfig sizing;
  FarFieldConfig farfield;
  HighOrderConfig highorder;
  ChecksConfig checks;
  OutputConfig output;
};

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
