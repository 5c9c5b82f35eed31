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
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/h_shell.hpp"
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
  double dihedral = 0.0;      ///< degrees (backend naca)
  std::string te = "blunt";   ///< "blunt" | "sharp"
  std::string tip = "flat";   ///< "flat" | "round"
  std::string wall = "plane";  ///< "plane" | "cylinder" | "cone" (backend naca: a streamwise fuselage)
  std::optional<double> wall_radius;  ///< the fuselage's radius at x = 0; unset: 1.5 chords
  std::optional<double> wall_angle;   ///< the cone's half angle, degrees; unset: 5
  std::array<double, 6> box = {-10, -10, 0, 11, 10, 10};  ///< xmin, ymin, zmin, xmax, ymax, zmax
};

/// [geometry.wall_plane]: the plane a body-only CAD file's body stands on (its root lies in it);
/// `normal` points into the fluid. Both keys or neither.
struct WallPlaneConfig {
  std::optional<std::array<double, 3>> point;
  std::optional<std::array<double, 3>> normal;
  bool given() const { return point || normal; }
};

/// [geometry.join]: an assembly whose body reaches into its wall without being joined to it (an
/// OpenVSP export): the file's faces of each part, by id ("#7") or name; joined at load, every
/// other face left out. Both keys or neither.
struct JoinConfig {
  std::optional<std::vector<std::string>> body;
  std::optional<std::vector<std::string>> wall;
  bool given() const { return body || wall; }
};

/// [geometry.farfield.sphere]
struct FarFieldSphereConfig {
  std::optional<std::array<double, 3>> centre;
  std::optional<double> radius;
};

/// geometry.farfield written as a table: the far field built around a body-only CAD file, one of a
/// box, a sphere, or a box `box_chords` root chords around the body.
struct FarFieldShapeConfig {
  std::optional<std::array<double, 6>> box;
  FarFieldSphereConfig sphere;
  std::optional<double> box_chords;
  bool given() const { return box || sphere.centre || sphere.radius || box_chords; }
};

/// [geometry]: where the CAD model comes from and which surfaces play which role.
struct GeometryConfig {
  std::string backend = "naca";  ///< registry name: "naca", "occ", "vendor"
  std::string source;            ///< CAD file, resolved against the config file's folder; empty: generator
  std::string units = "auto";    ///< unit of the file's numbers; "auto": the one it declares (generated: chord)
  double scale = 1.0;            ///< factor applied to a CAD file's coordinates at load
  std::optional<double> sew_tolerance;  ///< CAD files: sewing tolerance; unset: the backend's
  NacaConfig naca;
  /// Surface names or ids ("#7"), or "auto": found from the model (pipeline/roles.hpp).
  std::vector<std::string> body = {"auto"};
  std::string wall = "auto";
  std::vector<std::string> farfield = {"auto"};
  /// A body-only file: the wall and the far field built by the backend (both or neither); or an
  /// assembly: its parts joined and the far field built around them.
  WallPlaneConfig wall_plane;
  JoinConfig join;
  FarFieldShapeConfig farfield_shape;
  /// With wall_plane or join: the body's part beyond this plane (the side its normal points to)
  /// taken away and the cut closed flat: a tip pinched to zero thickness made blunt.
  WallPlaneConfig body_cut;
};

/// [nearfield]: the partition (topology) and the one-layer shell around the body.
struct NearFieldConfig {
  std::string topology = "O";  ///< "O", "C" (root junction block + wall layer), "H" (C + wake block)
  nearfield::ShellParams shell;
  nearfield::JunctionParams junction;  ///< C: which body-wall curves are concave corners, supported angles
};

/// [wall_layer]: the wall's boundary layer (C topology): one prism layer of `thickness` on the
/// wall, split like the wing's. thickness = 0: a slip wall (no wall layer, the O-type root).
struct WallLayerConfig {
  double thickness = 0.1;                   ///< delta_wall, model units
  ho::LayerDistribution split;              ///< layers, ratio
  std::optional<double> first_cell_height;  ///< instead of ratio: height of the first layer
  /// Optional, as boundary_layer's: the ratio linear along A -> B (by each wall vertex's projection),
  /// ratio_end at B; e.g. a wall layer growing downstream. Both keys or neither.
  std::optional<std::array<double, 6>> ratio_line;
  std::optional<double> ratio_end;
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
  /// Instead of ratio or first_cell_height: the first cell's y+ at a Reynolds number based on
  /// reference_length (unset: the chord), through a flat-plate skin-friction correlation
  /// (y_plus_first_cell_height). Both y_plus and reynolds, or neither.
  std::optional<double> y_plus;
  std::optional<double> reynolds;
  std::optional<double> reference_length;
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
  /// The pieces of a split element take the bounds their coarse element's det J gives them
  /// (ho::certify_pieces) instead of a Bernstein expansion of their own; false: every element is
  /// certified on its own nodes (the reference; same verdicts and figures to rounding, slower).
  bool inherit_bounds = true;
};

/// [output]
/// Which solver's import rules the mesh must meet beyond every format's own (docs/solvers.md).
enum class OutputTarget {
  Any,   ///< the method's elements as built (hex blocks with pyramids on their skin quads)
  Pyfr,  ///< PyFR: no pyramid on a base that is not a parallelogram (ho::split_pyramid_columns), order <= 4
};

struct OutputConfig {
  std::vector<std::string> formats = {"msh41", "vtu"};  ///< names from output_formats()
  OutputTarget target = OutputTarget::Any;
  std::string directory = ".";   ///< resolved against the current directory
  std::string basename = "mesh";
  bool allow_invalid = false;    ///< write the mesh even when a check fails
  bool pictures = false;         ///< SVG pictures beside the mesh (pictures.hpp)
  double picture_station = 0.4;  ///< where the spanwise cut is, as a fraction of the span
};

struct Config {
  GeometryConfig geometry;
  NearFieldConfig nearfield;
  BoundaryLayerConfig boundary_layer;
  WallLayerConfig wall_layer;
  nearfield::WakeParams wake;  ///< [wake]: the H-type wake block
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
  /// The section's key in its parent may hold a value instead, read by the parent's row of the same
  /// name (geometry.farfield: surface names, or the table of the far field to build).
  bool or_value = false;
  /// Its keys and nested sections are alternatives, one of them given (geometry.farfield: box |
  /// sphere | box_chords): a --set of one replaces the file's other ones.
  bool alternatives = false;
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

/// Skin-friction coefficient of a turbulent flat plate at Reynolds number `reynolds`:
/// Cf = 0.026 Re^(-1/7) (F. M. White, Fluid Mechanics, 7th ed., eq. 7.45, from the 1/7-power law).
double flat_plate_skin_friction(double reynolds);

/// First-cell height h giving `y_plus` on a plate of length `length` at Reynolds number `reynolds`
/// (based on `length`): u_tau = U sqrt(Cf / 2), nu = U length / Re, h = y+ nu / u_tau
/// = y+ length / (Re sqrt(Cf / 2)). Inverse: y_plus_of_height.
double y_plus_first_cell_height(double y_plus, double reynolds, double length);
double y_plus_of_height(double height, double reynolds, double length);

/// The layer with first_cell_height set from y_plus and reynolds when they are given (`chord` is
/// the reference length unless reference_length is set); unchanged otherwise.
BoundaryLayerConfig resolve_y_plus(BoundaryLayerConfig layer, double chord);

/// Ratio of the boundary layer: `ratio`, or the r solving h1 (r^N - 1) / (r - 1) = thickness when
/// first_cell_height h1 is given.
double effective_layer_ratio(const BoundaryLayerConfig& layer, double thickness);
/// The same for the wall layer.
double effective_wall_ratio(const WallLayerConfig& layer);
/// Whether the run builds the C-type junction (topology "C" or "H" and a wall layer of thickness > 0).
bool builds_junction(const Config& config);

}  // namespace semimesh::pipeline
