// Config parsing: defaults, every section, errors that name the key and the line, --set overrides.
#include "semimesh/pipeline/config.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include "temp_path.hpp"

namespace semimesh::pipeline {
namespace {

// The message of the ConfigError thrown by parsing `text` (fails the test if nothing is thrown).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_config(text, "case.toml", {}, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return {};
}

TEST(Config, DefaultsAreThePapersCase) {
  const Config c = parse_config("", "empty.toml");
  EXPECT_EQ(c.geometry.backend, "naca");
  EXPECT_EQ(c.geometry.naca.code, "0012");
  EXPECT_EQ(c.geometry.naca.chord, 1.0);
  EXPECT_EQ(c.geometry.naca.te, "blunt");
  EXPECT_EQ(c.geometry.body, (std::vector<std::string>{"auto"}));
  EXPECT_EQ(c.geometry.wall, "auto");
  EXPECT_EQ(c.geometry.farfield, (std::vector<std::string>{"auto"}));
  EXPECT_EQ(c.wake.te_base, "auto");
  EXPECT_EQ(c.nearfield.topology, "O");
  EXPECT_EQ(c.boundary_layer.split.layers, 5);
  EXPECT_EQ(c.boundary_layer.split.ratio, 2.0);
  EXPECT_FALSE(c.boundary_layer.first_cell_height.has_value());
  EXPECT_EQ(c.highorder.order, 4);
  EXPECT_EQ(c.highorder.node_set, ho::NodeSet::GLL);
  EXPECT_EQ(c.highorder.placement, ho::NodePlacement::Parameter);
  EXPECT_EQ(c.highorder.spring_iterations, 50);
  // Far field about ten chords from the wing.
  EXPECT_LE(c.geometry.naca.box[0], -9.0);
  EXPECT_GE(c.geometry.naca.box[3], 10.0);
  EXPECT_GE(c.geometry.naca.box[5], 9.0);
}

TEST(Config, ReadsEverySection) {
  const Config c = parse_config(R"(
[geometry]
backend = "occ"
units = "m"
body = ["upper", "lower", "tip"]
wall = "floor"
farfield = ["a", "b"]
[geometry.naca]
code = "2412"
chord = 2
span = 4.5
taper = 0.5
sweep = 10
te = "sharp"
box = [-5, -6, 0, 7, 8, 9]
[nearfield]
topology = "O"
thickness = 0.2
smoothing_passes = 3
min_thickness_fraction = 0.3
reduction_factor = 0.5
gradation = 0.25
[boundary_layer]
layers = 7
ratio = 1.5
[sizing]
max_size = 1.5
min_size = 0.01
curvature_segments = 6
gradation = 1.3
le_size = 0.03
te_size = 0.02
chordwise = 40
spanwise = 12
[farfield]
box_size = 3
wall_size = 0.7
growth = 1.1
radius_edge_ratio = 1.8
max_volume = 2.5
[highorder]
order = 3
node_set = "equispaced"
node_placement = "springs"
spring_iterations = 20
[output]
formats = ["msh22", "nektar"]
directory = "out"
basename = "wing"
allow_invalid = true
)",
                                "case.toml");
  EXPECT_EQ(c.geometry.backend, "occ");
  EXPECT_EQ(c.geometry.units, "m");
  EXPECT_EQ(c.geometry.body, (std::vector<std::string>{"upper", "lower", "tip"}));
  EXPECT_EQ(c.geometry.wall, "floor");
  EXPECT_EQ(c.geometry.farfield, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(c.geometry.naca.code, "2412");
  EXPECT_EQ(c.geometry.naca.chord, 2.0);
  EXPECT_EQ(c.geometry.naca.span, 4.5);
  EXPECT_EQ(c.geometry.naca.taper, 0.5);
  EXPECT_EQ(c.geometry.naca.sweep, 10.0);
  EXPECT_EQ(c.geometry.naca.te, "sharp");
  EXPECT_EQ(c.geometry.naca.box, (std::array<double, 6>{-5, -6, 0, 7, 8, 9}));
  EXPECT_EQ(c.nearfield.shell.thickness, 0.2);
  EXPECT_EQ(c.nearfield.shell.normal_smoothing_passes, 3);
  EXPECT_EQ(c.nearfield.shell.min_thickness_fraction, 0.3);
  EXPECT_EQ(c.nearfield.shell.reduction_factor, 0.5);
  EXPECT_EQ(c.nearfield.shell.gradation, 0.25);
  EXPECT_EQ(c.boundary_layer.split.layers, 7);
  EXPECT_EQ(c.boundary_layer.split.ratio, 1.5);
  EXPECT_EQ(c.sizing.size.max_size, 1.5);
  EXPECT_EQ(c.sizing.size.min_size, 0.01);
  EXPECT_EQ(c.sizing.size.curvature_segments, 6.0);
  EXPECT_EQ(c.sizing.size.gradation, 1.3);
  EXPECT_EQ(c.sizing.size.le_size, 0.03);
  EXPECT_EQ(c.sizing.size.te_size, 0.02);
  EXPECT_EQ(c.sizing.chordwise, 40);
  EXPECT_EQ(c.sizing.spanwise, 12);
  EXPECT_EQ(c.farfield.box_size, 3.0);
  EXPECT_EQ(c.farfield.wall_size, 0.7);
  EXPECT_EQ(c.farfield.growth, 1.1);
  EXPECT_EQ(c.farfield.radius_edge_ratio, 1.8);
  EXPECT_EQ(c.farfield.max_volume, 2.5);
  EXPECT_EQ(c.highorder.order, 3);
  EXPECT_EQ(c.highorder.node_set, ho::NodeSet::Equispaced);
  EXPECT_EQ(c.highorder.placement, ho::NodePlacement::Springs);
  EXPECT_EQ(c.highorder.spring_iterations, 20);
  EXPECT_EQ(c.output.formats, (std::vector<std::string>{"msh22", "nektar"}));
  EXPECT_EQ(c.output.directory, "out");
  EXPECT_EQ(c.output.basename, "wing");
  EXPECT_TRUE(c.output.allow_invalid);
}

TEST(Config, UnitsAndSewingAreCheckedAgainstTheSource) {
  EXPECT_NE(error_of("[geometry]\nunits = \"furlong\"\n").find("geometry.units = \"furlong\": expected \"auto\", \"mm\""),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nsource = \"wing.step\"\nbackend = \"occ\"\nunits = \"chord\"\n")
                .find("a length unit for a CAD file"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nsew_tolerance = 0.01\n").find("unset for a generated wing"), std::string::npos);
  const Config c = parse_config("[geometry]\nsource = \"wing.igs\"\nbackend = \"occ\"\nunits = \"m\"\nsew_tolerance = 1e-4\n",
                                "case.toml");
  EXPECT_EQ(c.geometry.units, "m");
  EXPECT_EQ(c.geometry.sew_tolerance, 1e-4);
}

// The rounded tip: the analytic backend only (occ's generated B-spline wing is flat-tipped), and
// with a sharp trailing edge at order 1 only (its conical point folds curved prisms).
TEST(Config, RoundTipIsTheAnalyticBackendsAndSharpAtOrderOneOnly) {
  EXPECT_EQ(parse_config("[geometry.naca]\ntip = \"round\"\n", "case.toml").geometry.naca.tip, "round");
  EXPECT_NE(error_of("[geometry.naca]\ntip = \"domed\"\n").find("geometry.naca.tip = \"domed\": expected \"flat\" or \"round\""),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nbackend = \"occ\"\n[geometry.naca]\ntip = \"round\"\n")
                .find("geometry.naca.tip = \"round\": expected \"flat\" for backend \"occ\""),
            std::string::npos);
  const std::string sharp = "[geometry.naca]\ntip = \"round\"\nte = \"sharp\"\n";
  EXPECT_NE(error_of(sharp + "[highorder]\norder = 4\n").find("geometry.naca.tip = \"round\": expected \"flat\" with te = \"sharp\""),
            std::string::npos);
  EXPECT_EQ(parse_config(sharp + "[highorder]\norder = 1\n", "case.toml").highorder.order, 1);
}

// The fuselage (geometry.naca.wall = "cylinder") is the analytic backend's and is the wall itself.
TEST(Config, CylinderWallIsTheAnalyticBackendsAndHasARadius) {
  const Config c = parse_config("[geometry.naca]\nwall = \"cylinder\"\nwall_radius = 2.5\n", "case.toml");
  EXPECT_EQ(c.geometry.naca.wall, "cylinder");
  EXPECT_EQ(c.geometry.naca.wall_radius, 2.5);
  EXPECT_FALSE(parse_config("", "case.toml").geometry.naca.wall_radius.has_value());
  EXPECT_NE(error_of("[geometry.naca]\nwall = \"sphere\"\n").find("geometry.naca.wall = \"sphere\": expected"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry.naca]\nwall_radius = 2.0\n").find("geometry.naca.wall_radius = 2: expected unset unless wall = \"cylinder\""),
            std::string::npos);
  EXPECT_EQ(parse_config("[geometry.naca]\nwall = \"cone\"\nwall_angle = -4.0\n", "case.toml").geometry.naca.wall_angle, -4.0);
  EXPECT_NE(error_of("[geometry.naca]\nwall = \"cylinder\"\nwall_angle = 3.0\n").find("geometry.naca.wall_angle = 3: expected unset unless wall = \"cone\""),
            std::string::npos);
  EXPECT_NE(error_of("[geometry.naca]\nwall = \"cone\"\nwall_angle = 31.0\n").find("geometry.naca.wall_angle = 31: expected (-30, 30)"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry.naca]\nwall = \"cylinder\"\nwall_radius = -1.0\n").find("geometry.naca.wall_radius = -1: expected > 0"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nbackend = \"occ\"\n[geometry.naca]\nwall = \"cylinder\"\n")
                .find("geometry.naca.wall = \"cylinder\": expected \"plane\" for backend \"occ\""),
            std::string::npos);
  EXPECT_NE(error_of("[geometry.naca]\nwall = \"cylinder\"\n[geometry.wall_plane]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\n")
                .find("geometry.naca.wall = \"cylinder\": expected \"plane\" with [geometry.wall_plane]"),
            std::string::npos);
}

TEST(Config, DihedralIsTheAnalyticBackends) {
  EXPECT_EQ(parse_config("[geometry.naca]\ndihedral = -6.0\n", "case.toml").geometry.naca.dihedral, -6.0);
  EXPECT_NE(error_of("[geometry.naca]\ndihedral = 50.0\n").find("geometry.naca.dihedral = 50: expected (-45, 45)"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nbackend = \"occ\"\n[geometry.naca]\ndihedral = 5.0\n")
                .find("geometry.naca.dihedral = 5: expected 0 for backend \"occ\""),
            std::string::npos);
}

TEST(Config, ABareStringIsAListOfOne) {
  EXPECT_EQ(parse_config("[geometry]\nbody = \"upper\"\n", "case.toml").geometry.body, (std::vector<std::string>{"upper"}));
  EXPECT_EQ(parse_config("[geometry]\nbody = [\"upper\", \"#3\"]\n", "case.toml").geometry.body,
            (std::vector<std::string>{"upper", "#3"}));
}

TEST(Config, UnknownKeyIsNamedWithItsLine) {
  const std::string message = error_of("[boundary_layer]\nlayers = 5\n\nratoi = 2.0\n");
  EXPECT_NE(message.find("case.toml:4"), std::string::npos) << message;
  EXPECT_NE(message.find("unknown key boundary_layer.ratoi"), std::string::npos) << message;
}

TEST(Config, UnknownSectionAndNestedKeyAreErrors) {
  EXPECT_NE(error_of("[meshing]\nx = 1\n").find("unknown key meshing"), std::string::npos);
  const std::string nested = error_of("[geometry.naca]\nchrod = 1\n");
  EXPECT_NE(nested.find("unknown key geometry.naca.chrod"), std::string::npos) << nested;
  EXPECT_NE(nested.find("case.toml:2"), std::string::npos) << nested;
}

TEST(Config, OutOfRangeValueNamesKeyValueAndRange) {
  const std::string message = error_of("[boundary_layer]\nratio = 0.5\n");
  EXPECT_EQ(message, "config error: case.toml:2: boundary_layer.ratio = 0.5: expected >= 1");
  EXPECT_NE(error_of("[highorder]\norder = 9\n").find("highorder.order = 9: expected an integer in [1, 8]"),
            std::string::npos);
  EXPECT_NE(error_of("[highorder]\nnode_placement = \"geodesic\"\n")
                .find("highorder.node_placement = \"geodesic\": expected \"parameter\" or \"springs\""),
            std::string::npos)
      << error_of("[highorder]\nnode_placement = \"geodesic\"\n");
  EXPECT_NE(error_of("[boundary_layer]\nratio_end = 1.5\n").find("boundary_layer.ratio_end = 1.5: expected together with"),
            std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\nratio_line = [0, 0, 0, 0, 0, 1]\n").find("boundary_layer.ratio_line"),
            std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\nratio_line = [1, 1, 1, 1, 1, 1]\nratio_end = 1\n").find("A != B"),
            std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\nratio_line = [0, 0, 0, 0, 0, 1]\nratio_end = 0.5\n")
                .find("boundary_layer.ratio_end = 0.5: expected >= 1"),
            std::string::npos);
  EXPECT_NE(error_of("[wall_layer]\nratio_end = 1.5\n").find("wall_layer.ratio_end = 1.5: expected together with"),
            std::string::npos);
  EXPECT_NE(error_of("[wall_layer]\nratio_line = [0, 0, 0, 1, 0, 0]\n").find("wall_layer.ratio_line"),
            std::string::npos);
  EXPECT_NE(error_of("[wall_layer]\nratio_line = [1, 1, 0, 1, 1, 0]\nratio_end = 1\n").find("A != B"),
            std::string::npos);
  EXPECT_NE(error_of("[highorder]\nspring_iterations = 0\n").find("highorder.spring_iterations = 0"), std::string::npos);
  EXPECT_NE(error_of("[sizing]\nmax_size = 0.1\nmin_size = 0.2\n").find("sizing.min_size = 0.2"), std::string::npos);
  EXPECT_NE(error_of("[output]\nformats = [\"stl\"]\n").find("output.formats"), std::string::npos);
  EXPECT_NE(error_of("[nearfield]\nthickness = -1\n").find("nearfield.thickness = -1: expected > 0"), std::string::npos);
}

TEST(Config, PyfrTargetWantsAnAsciiMshAndOrderAtMostFour) {
  EXPECT_EQ(parse_config("", "empty.toml").output.target, OutputTarget::Any);
  EXPECT_EQ(parse_config("[output]\ntarget = \"pyfr\"\nformats = [\"msh22\"]\n", "case.toml").output.target,
            OutputTarget::Pyfr);
  EXPECT_EQ(parse_config("[output]\ntarget = \"pyfr\"\nformats = [\"msh41-ascii\"]\n", "case.toml").output.target,
            OutputTarget::Pyfr);
  // "msh41" is binary (the default), "msh41-binary" its old name: PyFR reads neither.
  for (const char* binary : {"msh41", "msh41-binary"})
    EXPECT_NE(error_of(std::string("[output]\ntarget = \"pyfr\"\nformats = [\"") + binary + "\", \"vtu\"]\n")
                  .find("expected with target = \"pyfr\": \"msh41-ascii\" or \"msh22\" among them"),
              std::string::npos)
        << binary;
  EXPECT_NE(error_of("[output]\ntarget = \"pyfr\"\nformats = [\"msh41-ascii\"]\n[highorder]\norder = 5\n")
                .find("highorder.order = 5: expected at most 4 with output.target = \"pyfr\""),
            std::string::npos);
  EXPECT_NE(error_of("[output]\ntarget = \"nektar\"\n").find("output.target"), std::string::npos);
}

TEST(Config, ChecksFloorHasAPositiveDefaultAndARange) {
  EXPECT_EQ(parse_config("", "empty.toml").checks.min_scaled_jacobian, 1e-5);
  EXPECT_EQ(parse_config("[checks]\nmin_scaled_jacobian = 0.01\n", "case.toml").checks.min_scaled_jacobian, 0.01);
  EXPECT_EQ(parse_config("[checks]\nmin_scaled_jacobian = 0\n", "case.toml").checks.min_scaled_jacobian, 0.0);
  EXPECT_EQ(error_of("[checks]\nmin_scaled_jacobian = 1\n"),
            "config error: case.toml:2: checks.min_scaled_jacobian = 1: expected [0, 1)");
  EXPECT_NE(error_of("[checks]\nmin_scaled_jacobian = -0.1\n").find("checks.min_scaled_jacobian = -0.1"), std::string::npos);
  EXPECT_NE(error_of("[checks]\nfloor = 0.1\n").find("unknown key checks.floor"), std::string::npos);
}

TEST(Config, WrongTypeIsAnError) {
  EXPECT_NE(error_of("[boundary_layer]\nlayers = 2.5\n").find("boundary_layer.layers = 2.5: expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of("[geometry]\nbody = 3\n").find("expected a non-empty array of strings"), std::string::npos);
  EXPECT_NE(error_of("[geometry.naca]\nbox = [1, 2, 3]\n").find("expected an array of 6 numbers"), std::string::npos);
}

TEST(Config, SyntaxErrorGivesTheLine) {
  const std::string message = error_of("[sizing]\nmax_size = = 2\n");
  EXPECT_EQ(message.rfind("config error: case.toml:2:", 0), 0u) << message;
}

TEST(Config, HTopologyWithItsWakeBlock) {
  const Config c = parse_config("[nearfield]\ntopology = \"H\"\n[wake]\ndirection = [1.0, 0.2, 0.0]\nlength = 3.0\n"
                                "layers = 20\ngrowth = 1.1\nwidening = 5.0\ngap = 0.2\nratio_end = 1.2\n",
                                "case.toml");
  EXPECT_EQ(c.nearfield.topology, "H");
  EXPECT_EQ(c.wake.direction[1], 0.2);
  EXPECT_EQ(c.wake.length, 3.0);
  EXPECT_EQ(c.wake.layers, 20);
  EXPECT_EQ(c.wake.growth, 1.1);
  EXPECT_EQ(c.wake.widening_deg, 5.0);
  EXPECT_EQ(c.wake.gap, 0.2);
  EXPECT_EQ(c.wake.ratio_end, 1.2);
  EXPECT_TRUE(builds_junction(c));
}

TEST(Config, HTopologyNeedsAWallLayerAndRangedWakeKeys) {
  const std::string message = error_of("[nearfield]\ntopology = \"H\"\n[wall_layer]\nthickness = 0.0\n");
  EXPECT_NE(message.find("nearfield.topology"), std::string::npos) << message;
  EXPECT_NE(message.find("wall_layer.thickness"), std::string::npos) << message;
  EXPECT_NE(error_of("[nearfield]\ntopology = \"X\"\n").find("expected \"O\", \"C\" or \"H\""), std::string::npos);
  for (const char* bad : {"gap = 0.0", "length = -1.0", "layers = 0", "growth = 0.5", "widening = 45.0", "ratio_end = 0.9",
                          "direction = [1.0, 0.0]"}) {
    const std::string text = error_of(std::string("[wake]\n") + bad + "\n");
    const std::string key = std::string("wake.") + std::string(bad).substr(0, std::string(bad).find(' '));
    EXPECT_NE(text.find(key), std::string::npos) << bad << ": " << text;
    EXPECT_NE(text.find("case.toml:2"), std::string::npos) << bad << ": " << text;
  }
}

TEST(Config, CTopologyWithItsWallLayer) {
  const Config c = parse_config("[nearfield]\ntopology = \"C\"\njunction_min_angle = 70\n"
                                "[wall_layer]\nthickness = 0.05\nlayers = 4\nfirst_cell_height = 0.002\n",
                                "case.toml");
  EXPECT_EQ(c.nearfield.topology, "C");
  EXPECT_EQ(c.nearfield.junction.min_angle_deg, 70.0);
  EXPECT_EQ(c.wall_layer.thickness, 0.05);
  EXPECT_EQ(c.wall_layer.split.layers, 4);
  EXPECT_TRUE(builds_junction(c));
  const double r = effective_wall_ratio(c.wall_layer);
  EXPECT_NEAR(0.002 * (std::pow(r, 4) - 1) / (r - 1), 0.05, 1e-9);
  // thickness = 0: a slip wall, the O-type root.
  EXPECT_FALSE(builds_junction(parse_config("[nearfield]\ntopology = \"C\"\n[wall_layer]\nthickness = 0\n", "c.toml")));
  const std::string message = error_of("[wall_layer]\nthickness = -1\n");
  EXPECT_NE(message.find("wall_layer.thickness"), std::string::npos) << message;
  const std::string angles = error_of("[nearfield]\njunction_min_angle = 160\n");
  EXPECT_NE(angles.find("nearfield.junction_min_angle"), std::string::npos) << angles;
}

TEST(Config, SetOverridesTheFileAndIsNamedInErrors) {
  const Config c = parse_config("[boundary_layer]\nratio = 1.5\n", "case.toml", {},
                                {"boundary_layer.ratio=1.25", "geometry.backend=occ", "geometry.naca.box=[-1,-1,0,2,1,1]",
                                 "output.formats=[\"vtu\"]", "highorder.order = 2"});
  EXPECT_EQ(c.boundary_layer.split.ratio, 1.25);
  EXPECT_EQ(c.geometry.backend, "occ");  // a bare word is taken as a string
  EXPECT_EQ(c.geometry.naca.box, (std::array<double, 6>{-1, -1, 0, 2, 1, 1}));
  EXPECT_EQ(c.output.formats, (std::vector<std::string>{"vtu"}));
  EXPECT_EQ(c.highorder.order, 2);

  const std::string bad = error_of("", {"boundary_layer.ratio=0.5"});
  EXPECT_EQ(bad, "config error: --set boundary_layer.ratio=0.5: boundary_layer.ratio = 0.5: expected >= 1");
  EXPECT_NE(error_of("", {"sizing.maxsize=1"}).find("unknown key sizing.maxsize"), std::string::npos);
  EXPECT_NE(error_of("", {"novalue"}).find("expected key=value"), std::string::npos);
  EXPECT_NE(error_of("[highorder]\norder = 4\n", {"highorder.order.x=1"}).find("highorder.order is a value"), std::string::npos);
}

// y+ -> first-cell height against values computed by hand from Cf = 0.026 Re^(-1/7):
// Re = 1e6: Re^(1/7) = 7.196857, Cf = 3.612689e-3, sqrt(Cf/2) = 0.04250111, h = 1 / (1e6 x 0.04250111).
TEST(Config, YPlusGivesTheFirstCellHeight) {
  EXPECT_NEAR(flat_plate_skin_friction(1e6), 3.612689e-3, 1e-9);
  EXPECT_NEAR(y_plus_first_cell_height(1.0, 1e6, 1.0), 2.352880e-5, 1e-10);
  // Re = 5e5 on a 0.5 m chord with y+ = 30: Cf = 0.026 / 6.518363 = 3.988731e-3, h = 30 x 0.5 / (5e5 x 0.04465832).
  EXPECT_NEAR(y_plus_first_cell_height(30.0, 5e5, 0.5), 6.717673e-4, 1e-9);
  EXPECT_NEAR(y_plus_of_height(y_plus_first_cell_height(7.0, 3e6, 2.0), 3e6, 2.0), 7.0, 1e-12);

  const Config c = parse_config("[boundary_layer]\ny_plus = 1\nreynolds = 1e6\n", "case.toml");
  const BoundaryLayerConfig resolved = resolve_y_plus(c.boundary_layer, 1.0);
  ASSERT_TRUE(resolved.first_cell_height.has_value());
  EXPECT_NEAR(*resolved.first_cell_height, 2.352880e-5, 1e-10);
  const BoundaryLayerConfig half = resolve_y_plus(
      parse_config("[boundary_layer]\ny_plus = 1\nreynolds = 1e6\nreference_length = 0.5\n", "c.toml").boundary_layer, 1.0);
  EXPECT_NEAR(*half.first_cell_height, 0.5 * 2.352880e-5, 1e-10);
  EXPECT_NE(error_of("[boundary_layer]\ny_plus = 1\n").find("together with boundary_layer.reynolds"), std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\nreynolds = 1e6\n").find("together with boundary_layer.y_plus"), std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\ny_plus = 1\nreynolds = 1e6\nratio = 2\n").find("one of them"), std::string::npos);
  EXPECT_NE(error_of("[boundary_layer]\ny_plus = -1\nreynolds = 1e6\n").find("boundary_layer.y_plus = -1: expected > 0"),
            std::string::npos);
}

TEST(Config, FirstCellHeightGivesTheRatio) {
  const Config c = parse_config("[nearfield]\nthickness = 0.1\n[boundary_layer]\nlayers = 5\nfirst_cell_height = 0.01\n",
                                "case.toml");
  ASSERT_TRUE(c.boundary_layer.first_cell_height.has_value());
  // With r = 2 the five layers are 1 + 2 + 4 + 8 + 16 = 31 first cells: h1 = thickness / 31.
  BoundaryLayerConfig layer;
  layer.split.layers = 5;
  layer.first_cell_height = 0.1 / 31.0;
  EXPECT_NEAR(effective_layer_ratio(layer, 0.1), 2.0, 1e-10);
  layer.first_cell_height = 0.02;
  EXPECT_NEAR(effective_layer_ratio(layer, 0.1), 1.0, 1e-10);
  EXPECT_NE(error_of("[boundary_layer]\nratio = 2\nfirst_cell_height = 0.001\n").find("not both"), std::string::npos);
  EXPECT_NE(error_of("[nearfield]\nthickness = 0.1\n[boundary_layer]\nlayers = 5\nfirst_cell_height = 0.05\n")
                .find("boundary_layer.first_cell_height = 0.05"),
            std::string::npos);
}

TEST(Config, LoadResolvesTheSourceAgainstTheConfigFolder) {
  const auto dir = semimesh::test::temp_path("config_test");
  std::filesystem::create_directories(dir);
  const auto path = dir / "case.toml";
  std::ofstream(path) << "[geometry]\nbackend = \"occ\"\nsource = \"wing.step\"\n";
  const Config c = load_config(path.string());
  EXPECT_EQ(c.geometry.source, (dir / "wing.step").string());
  std::filesystem::remove_all(dir);
  EXPECT_THROW(load_config((dir / "missing.toml").string()), ConfigError);
}

TEST(Config, TheExamplesParse) {
  for (const char* name : {"naca0012_wing.toml", "naca0012_wing_o.toml", "naca0012_wing_c.toml"}) {
    const Config c = load_config(std::string(SEMIMESH_SOURCE_DIR) + "/examples/" + name);
    EXPECT_EQ(c.highorder.order, 4) << name;
    EXPECT_EQ(c.boundary_layer.split.layers, 5) << name;
    EXPECT_EQ(c.boundary_layer.split.ratio, 2.0) << name;
    EXPECT_NEAR(c.nearfield.shell.thickness, 0.1, 0.05) << name;
  }
  // The paper's example is its H-type near field.
  const Config paper = load_config(std::string(SEMIMESH_SOURCE_DIR) + "/examples/naca0012_wing.toml");
  EXPECT_EQ(paper.nearfield.topology, "H");
  EXPECT_GT(paper.wake.gap, 0.0);
  EXPECT_EQ(paper.wake.ratio_end, 1.0);
}

}  // namespace
}  // namespace semimesh::pipeline

namespace semimesh::pipeline {
namespace {

// A body-only file: the wall plane and the far field to build, each far-field form.
TEST(Config, WallPlaneAndFarFieldToBuild) {
  const char* const plane = "[geometry]\nbackend = \"occ\"\nsource = \"m6.stp\"\n"
                            "wall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n";
  Config c = parse_config(std::string(plane) + "farfield = { box = [-1, -2, -3, 4, 5, 6] }\n", "case.toml");
  ASSERT_TRUE(c.geometry.wall_plane.normal.has_value());
  EXPECT_EQ((*c.geometry.wall_plane.normal)[1], 1.0);
  ASSERT_TRUE(c.geometry.farfield_shape.box.has_value());
  EXPECT_EQ((*c.geometry.farfield_shape.box)[5], 6.0);
  EXPECT_EQ(c.geometry.farfield, (std::vector<std::string>{"auto"}));  // the roles are then found
  c = parse_config(std::string(plane) + "farfield = { sphere = { centre = [1, 2, 3], radius = 9 } }\n", "case.toml");
  EXPECT_EQ(c.geometry.farfield_shape.sphere.radius, 9.0);
  EXPECT_EQ((*c.geometry.farfield_shape.sphere.centre)[2], 3.0);
  c = parse_config(std::string(plane) + "farfield = { box_chords = 20 }\n", "case.toml");
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 20.0);
  // Surface names still work, and --set reaches the table's keys.
  c = parse_config("[geometry]\nfarfield = [\"a\", \"b\"]\n", "case.toml");
  EXPECT_EQ(c.geometry.farfield, (std::vector<std::string>{"a", "b"}));
  c = parse_config(plane, "case.toml", {}, {"geometry.farfield.box_chords=5"});
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 5.0);
}

TEST(Config, WallPlaneAndFarFieldErrorsNameTheKey) {
  const std::string file = "[geometry]\nbackend = \"occ\"\nsource = \"m6.stp\"\n";
  const std::string plane = "wall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n";
  std::string e = error_of(file + plane);  // no far field
  EXPECT_NE(e.find("geometry.wall_plane"), std::string::npos) << e;
  EXPECT_NE(e.find("geometry.farfield = {box"), std::string::npos) << e;
  e = error_of(file + "farfield = { box_chords = 20 }\n");  // no plane
  EXPECT_NE(e.find("geometry.wall_plane"), std::string::npos) << e;
  e = error_of(file + "wall_plane = { point = [0, 0, 0], normal = [0, 0, 0] }\nfarfield = { box_chords = 20 }\n");
  EXPECT_NE(e.find("geometry.wall_plane.normal = [ 0, 0, 0 ]"), std::string::npos) << e;
  EXPECT_NE(e.find("non-zero"), std::string::npos) << e;
  e = error_of(file + plane + "farfield = { box_chords = 20, box = [0, 0, 0, 1, 1, 1] }\n");
  EXPECT_NE(e.find("one of box, sphere or box_chords"), std::string::npos) << e;
  e = error_of(file + plane + "farfield = { box = [0, 0, 0, 1, -1, 1] }\n");
  EXPECT_NE(e.find("geometry.farfield.box = [ 0, 0, 0, 1, -1, 1 ]"), std::string::npos) << e;
  e = error_of(file + plane + "farfield = { box_chords = -2 }\n");
  EXPECT_NE(e.find("geometry.farfield.box_chords = -2"), std::string::npos) << e;
  e = error_of(file + plane + "farfield = { sphere = { radius = 5 } }\n");
  EXPECT_NE(e.find("geometry.farfield.sphere.radius = 5"), std::string::npos) << e;
  e = error_of(file + plane + "farfield = { box_chords = 5, cylinder = 5 }\n");
  EXPECT_NE(e.find("unknown key geometry.farfield.cylinder"), std::string::npos) << e;
}

// geometry.body_cut: a point and a non-zero normal, on a CAD file's body the far field is built
// around (cli.body_cut_pinched_tip_run runs it).
TEST(Config, BodyCutGoesWithABodyTheFarFieldIsBuiltAround) {
  const std::string file = "[geometry]\nbackend = \"occ\"\nsource = \"vsp.stp\"\n";
  const std::string domain = "wall_plane = { point = [0, 0, 0], normal = [0, 0, 1] }\nfarfield = { box_chords = 20 }\n";
  const Config c = parse_config(file + domain + "body_cut = { point = [0, 0, 0.9], normal = [0, 0, 1] }\n", "case.toml");
  ASSERT_TRUE(c.geometry.body_cut.point.has_value());
  EXPECT_EQ((*c.geometry.body_cut.point)[2], 0.9);
  std::string e = error_of(file + "body_cut = { point = [0, 0, 0.9], normal = [0, 0, 1] }\n");  // no domain
  EXPECT_NE(e.find("geometry.body_cut"), std::string::npos) << e;
  EXPECT_NE(e.find("[geometry.wall_plane] or [geometry.join]"), std::string::npos) << e;
  e = error_of(file + domain + "body_cut = { point = [0, 0, 0.9] }\n");
  EXPECT_NE(e.find("geometry.body_cut.point = [ 0, 0, 0.9"), std::string::npos) << e;
  EXPECT_NE(e.find("together with geometry.body_cut.normal"), std::string::npos) << e;
  e = error_of(file + domain + "body_cut = { point = [0, 0, 0.9], normal = [0, 0, 0] }\n");
  EXPECT_NE(e.find("geometry.body_cut.normal = [ 0, 0, 0 ]"), std::string::npos) << e;
}

// An assembly's parts to join (geometry.join): both, with a far field box or sphere, for a CAD file.
TEST(Config, JoinNamesBothPartsAndABoxForACadFile) {
  const std::string file = "[geometry]\nbackend = \"occ\"\nsource = \"vsp.stp\"\n";
  const std::string box = "farfield = { box = [-8, -8, -8, 9, 9, 8] }\n";
  const std::string join = "[geometry.join]\nbody = [\"#3\", \"wing\"]\nwall = [\"#0\"]\n";
  const Config c = parse_config(file + box + join, "case.toml");
  EXPECT_EQ(c.geometry.join.body, (std::vector<std::string>{"#3", "wing"}));
  EXPECT_EQ(c.geometry.join.wall, (std::vector<std::string>{"#0"}));
  EXPECT_FALSE(parse_config(file + box + "wall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n", "case.toml")
                   .geometry.join.given());
  std::string e = error_of(file + join);  // no far field
  EXPECT_NE(e.find("geometry.join.body"), std::string::npos) << e;
  EXPECT_NE(e.find("geometry.farfield = {box = [...]}"), std::string::npos) << e;
  e = error_of(file + "farfield = { box_chords = 20 }\n" + join);
  EXPECT_NE(e.find("box_chords measures a root"), std::string::npos) << e;
  e = error_of(file + box + "[geometry.join]\nbody = [\"#3\"]\n");
  EXPECT_NE(e.find("geometry.join.wall"), std::string::npos) << e;
  e = error_of(file + box + "[geometry.join]\nbody = []\nwall = [\"#0\"]\n");
  EXPECT_NE(e.find("geometry.join.body"), std::string::npos) << e;
  e = error_of(file + box + "wall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n" + join);
  EXPECT_NE(e.find("unset with [geometry.wall_plane]"), std::string::npos) << e;
  e = error_of("[geometry]\nbackend = \"naca\"\n" + box + join);
  EXPECT_NE(e.find("a CAD file's faces"), std::string::npos) << e;
}

// geometry.farfield holds one of box | sphere | box_chords: a --set of one replaces the file's
// other (it used to be added beside it and the run refused both); a --set inside the table replaces
// a file's surface names. The wall plane's pieces are set one by one, the other kept.
TEST(Config, SetOfOneFarFieldShapeReplacesTheFilesOther) {
  const std::string file = "[geometry]\nbackend = \"occ\"\nsource = \"m6.stp\"\n"
                           "wall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n";
  const std::string box = file + "farfield = { box = [-8, -8, -8, 9, 9, 8] }\n";
  Config c = parse_config(box, "case.toml", {}, {"geometry.farfield.box_chords=20"});
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 20.0);
  EXPECT_FALSE(c.geometry.farfield_shape.box.has_value());
  c = parse_config(box, "case.toml", {}, {"geometry.farfield.sphere.centre=[1, 2, 3]", "geometry.farfield.sphere.radius=9"});
  EXPECT_EQ(c.geometry.farfield_shape.sphere.radius, 9.0);
  EXPECT_FALSE(c.geometry.farfield_shape.box.has_value());
  c = parse_config(file + "farfield = { box_chords = 20 }\n", "case.toml", {}, {"geometry.farfield.box=[0, 0, 0, 1, 2, 3]"});
  EXPECT_EQ(c.geometry.farfield_shape.box, (std::array<double, 6>{0, 0, 0, 1, 2, 3}));
  EXPECT_FALSE(c.geometry.farfield_shape.box_chords.has_value());
  // Within the sphere only the key set changes.
  c = parse_config(file + "farfield = { sphere = { centre = [1, 2, 3], radius = 9 } }\n", "case.toml", {},
                   {"geometry.farfield.sphere.radius=5"});
  EXPECT_EQ(c.geometry.farfield_shape.sphere.radius, 5.0);
  EXPECT_EQ(c.geometry.farfield_shape.sphere.centre, (std::array<double, 3>{1, 2, 3}));
  // A half-given sphere replacing a box is named as such; an unknown key replaces nothing.
  std::string e = error_of(box, {"geometry.farfield.sphere.radius=9"});
  EXPECT_NE(e.find("--set geometry.farfield.sphere.radius=9"), std::string::npos) << e;
  EXPECT_NE(e.find("together with geometry.farfield.sphere.centre"), std::string::npos) << e;
  e = error_of(box, {"geometry.farfield.cylinder=5"});
  EXPECT_NE(e.find("unknown key geometry.farfield.cylinder"), std::string::npos) << e;
  // Surface names in the file: the far field to build replaces them.
  c = parse_config(std::string("[geometry]\nbackend = \"occ\"\nsource = \"m6.stp\"\nfarfield = [\"outer\"]\n"),
                   "case.toml", {},
                   {"geometry.wall_plane.point=[0, 0, 0]", "geometry.wall_plane.normal=[0, 1, 0]",
                    "geometry.farfield.box_chords=20"});
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 20.0);
  EXPECT_EQ(c.geometry.farfield, (std::vector<std::string>{"auto"}));
  // The wall plane's pieces.
  c = parse_config(box, "case.toml", {}, {"geometry.wall_plane.normal=[0, 0, 1]"});
  EXPECT_EQ(c.geometry.wall_plane.normal, (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(c.geometry.wall_plane.point, (std::array<double, 3>{0, 0, 0}));
  c = parse_config(box, "case.toml", {}, {"geometry.wall_plane.point=[1, 2, 3]"});
  EXPECT_EQ(c.geometry.wall_plane.point, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(c.geometry.wall_plane.normal, (std::array<double, 3>{0, 1, 0}));
}

// The generated wing stands on z = 0 in a box: only that plane and a box far field apply to it.
TEST(Config, AGeneratedWingTakesTheWallZEqualsZeroAndABox) {
  const Config c = parse_config("[geometry]\nwall_plane = { point = [1, 2, 0], normal = [0, 0, 2] }\n"
                                "farfield = { box_chords = 4 }\n", "case.toml");
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 4.0);
  std::string e = error_of("[geometry]\nwall_plane = { point = [0, 0, 0], normal = [0, 1, 0] }\n"
                           "farfield = { box_chords = 4 }\n");
  EXPECT_NE(e.find("geometry.wall_plane.normal = [ 0, 1, 0 ]"), std::string::npos) << e;
  EXPECT_NE(e.find("z = 0"), std::string::npos) << e;
  e = error_of("[geometry]\nwall_plane = { point = [0, 0, 0], normal = [0, 0, 1] }\n"
               "farfield = { sphere = { centre = [0, 0, 0], radius = 9 } }\n");
  EXPECT_NE(e.find("geometry.farfield.sphere.centre = [ 0, 0, 0 ]"), std::string::npos) << e;
  EXPECT_NE(e.find("needs a CAD file"), std::string::npos) << e;
}

}  // namespace
}  // namespace semimesh::pipeline
