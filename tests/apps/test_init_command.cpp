// `semimesh init`: the text it writes is read back by the config reader as the defaults, key by key.
#include "init_command.hpp"

#include "cad_info.hpp"
#include "init_from_cad.hpp"
#include "model_as_run.hpp"
#include "semimesh/cad/trimmed_area.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/backends/builtin.hpp"
#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/roles.hpp"
#include "semimesh/surface/cad_roles.hpp"
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/shell_size_limit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include "temp_path.hpp"

namespace semimesh::app {
namespace {

TEST(InitCommand, TheDefaultConfigReadsBackAsTheDefaults) {
  const std::string text = default_config_text();
  const pipeline::Config parsed = pipeline::parse_config(text, "init.toml");
  const pipeline::Config defaults;
  int keys = 0;
  for (const pipeline::ConfigSection& section : pipeline::config_sections())
    for (const params::Key<pipeline::Config>& key : section.keys) {
      EXPECT_EQ(params::to_text(key.get(parsed)), params::to_text(key.get(defaults))) << section.name << "." << key.name;
      EXPECT_NE(text.find("# " + key.doc), std::string::npos) << "no doc line for " << section.name << "." << key.name;
      ++keys;
    }
  EXPECT_GT(keys, 30);
}

// geometry.farfield is surface names or the table of the far field to build: the text holds one of
// them (TOML cannot have both), and reads back either way.
TEST(InitCommand, TheFarFieldToBuildReadsBack) {
  pipeline::Config values;
  values.geometry.backend = "occ";
  values.geometry.source = "m6.stp";
  values.geometry.wall_plane.point = {0.0, 0.0, 0.0};
  values.geometry.wall_plane.normal = {0.0, 1.0, 0.0};
  values.geometry.farfield_shape.box_chords = 20.0;
  const std::string text = config_text(values, "a body-only file\n");
  const pipeline::Config parsed = pipeline::parse_config(text, "init.toml");
  EXPECT_EQ(parsed.geometry.farfield_shape.box_chords, 20.0);
  EXPECT_EQ(parsed.geometry.wall_plane.normal, values.geometry.wall_plane.normal);
  EXPECT_NE(text.find("\n[geometry.farfield]\n"), std::string::npos);
  EXPECT_EQ(text.find("\nfarfield = "), std::string::npos) << "the surface-name key is left out";
  // Unset, the table's header is a comment and the names key is there.
  const std::string defaults = default_config_text();
  EXPECT_NE(defaults.find("\n# [geometry.farfield]\n"), std::string::npos);
  EXPECT_NE(defaults.find("\nfarfield = [\"auto\"]"), std::string::npos);
}

TEST(InitCommand, KeepsAnExistingFileUnlessForced) {
  const std::filesystem::path path = semimesh::test::temp_path("init.toml");
  std::filesystem::remove(path);
  std::ostringstream out, err;
  ASSERT_EQ(run_init_command({path.string(), false, {}}, out, err), 0) << err.str();
  ASSERT_TRUE(std::filesystem::exists(path));
  std::filesystem::resize_file(path, 10);
  EXPECT_EQ(run_init_command({path.string(), false, {}}, out, err), 1);
  EXPECT_NE(err.str().find("exists"), std::string::npos) << err.str();
  EXPECT_EQ(std::filesystem::file_size(path), 10u);  // untouched
  EXPECT_EQ(run_init_command({path.string(), true, {}}, out, err), 0);
  EXPECT_EQ(std::filesystem::file_size(path), default_config_text().size());
  std::filesystem::remove(path);
}

std::string nekmesh_wing() { return std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp"; }

// init --cad on the NekMesh STEP wing: the file reads back with the roles the detection finds
// (resolved through the run's own role resolution), the file's unit and source, and every length
// of the defaults times the root chord.
TEST(InitCommand, ACadFileGetsItsRolesAndLengthsScaledByItsChord) {
  if (!std::filesystem::exists(nekmesh_wing())) GTEST_SKIP() << nekmesh_wing() << " not found (see shared/testdata/cad/README.md)";
  const std::filesystem::path dir = semimesh::test::temp_path("init_cad");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "wing.toml").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_init_command({path, false, nekmesh_wing()}, out, err), 0) << err.str();
  const pipeline::Config c = pipeline::load_config(path);
  EXPECT_EQ(c.geometry.backend, "occ");
  EXPECT_TRUE(std::filesystem::equivalent(c.geometry.source, nekmesh_wing()));
  EXPECT_EQ(c.geometry.units, "mm");

  const auto model = backends::default_registry().load("occ", cad::Source{nekmesh_wing(), {}});
  const surface::CadRoles found = surface::detect_cad_roles(*model);
  // The base found: the paper's H-type near field (before, init wrote "O" whatever the file).
  EXPECT_EQ(c.nearfield.topology, "H");
  EXPECT_GT(c.wall_layer.thickness, 0.0);
  const pipeline::Roles roles = pipeline::resolve_roles(*model, c);
  EXPECT_EQ(roles.wall, found.wall);
  EXPECT_EQ(roles.body, found.body);
  EXPECT_EQ(roles.farfield, found.farfield);
  EXPECT_EQ(roles.te_base, found.te_base);

  // min_size: what the shell needs at the tip; the curves are unnamed (edge_<id>), so le_size and
  // te_size act on nothing and max_size is a chord / 8.
  const std::array<std::string, 4> kNotScaled = {"sizing.min_size", "sizing.max_size", "sizing.le_size", "sizing.te_size"};
  EXPECT_NEAR(c.sizing.size.max_size, found.chord / 8, 1e-3 * found.chord);
  EXPECT_EQ(c.sizing.size.le_size, 0.0);
  EXPECT_EQ(c.sizing.size.te_size, 0.0);
  const pipeline::Config defaults;
  for (const pipeline::ConfigSection& section : pipeline::config_sections())
    for (const params::Key<pipeline::Config>& key : section.keys)
      if (const std::string name = section.name + "." + key.name;
          std::count(length_keys().begin(), length_keys().end(), name) &&
          !std::count(kNotScaled.begin(), kNotScaled.end(), name)) {
        const double scaled = std::get<double>(key.get(defaults)) * found.chord;
        EXPECT_NEAR(std::get<double>(key.get(c)), scaled, 1e-3 * scaled) << section.name << "." << key.name;
      }
  EXPECT_GT(c.nearfield.shell.thickness, 100.0);  // a tenth of a chord of about 1.2 m, in mm

  // min_size: the chord-scaled default (6 mm) is more than the shell allows on the tip's 1.5 mm
  // trailing-edge radius; init writes what `run`'s size check (the shell limit at order > 1) accepts.
  const double scaled_min = defaults.sizing.size.min_size * found.chord;
  EXPECT_LT(c.sizing.size.min_size, scaled_min);
  EXPECT_GT(c.sizing.size.min_size, 0.5);  // mm: not absurdly fine
  ASSERT_GT(c.highorder.order, 1);
  const surface::ShellSizing shell{c.nearfield.shell.thickness, roles.body};
  EXPECT_NO_THROW(surface::shell_size_sources(*model, shell, c.sizing.size));
  surface::SizeParams chord_scaled = c.sizing.size;
  chord_scaled.min_size = scaled_min;
  EXPECT_THROW(surface::shell_size_sources(*model, shell, chord_scaled), surface::SurfaceMeshError);  // as before
  std::filesystem::remove_all(dir);
}

TEST(InitCommand, AFileWithoutAWallIsRefusedAndNothingWritten) {
  const std::filesystem::path path = semimesh::test::temp_path("init_missing.toml");
  std::filesystem::remove(path);
  std::ostringstream out, err;
  EXPECT_EQ(run_init_command({path.string(), false, "/no/such/wing.step"}, out, err), 1);
  EXPECT_NE(err.str().find("/no/such/wing.step"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(path));
}

// The ONERA M6 file holds the body alone, a closed solid with its root on y = 0: init finds that
// root cap and writes the wall plane and a box around the body (it was refused: no wall).
TEST(InitCommand, BodyOnlyFileGetsItsWallPlaneFromTheRootCap) {
  const std::string m6 = std::string(SEMIMESH_TESTDATA_DIR) + "/cad/onera_m6_sharp_te.stp";
  if (!std::filesystem::exists(m6)) GTEST_SKIP() << m6 << " not found (see shared/testdata/cad/README.md)";
  const std::filesystem::path path = semimesh::test::temp_path("init_m6.toml");
  std::ostringstream out, err;
  ASSERT_EQ(run_init_command({path.string(), false, m6}, out, err), 0) << err.str();
  const pipeline::Config c = pipeline::load_config(path.string());
  ASSERT_TRUE(c.geometry.wall_plane.point && c.geometry.wall_plane.normal);
  EXPECT_NEAR((*c.geometry.wall_plane.point)[1], 0.0, 1e-6);
  EXPECT_NEAR((*c.geometry.wall_plane.normal)[1], 1.0, 1e-9);
  EXPECT_EQ(c.geometry.farfield_shape.box_chords, 10.0);
  EXPECT_EQ(c.geometry.wall, "wall");
  // No curve named leading_edge / trailing_edge: the chord resolved by max_size = chord / 8.
  EXPECT_NEAR(c.sizing.size.max_size, 810.49 / 8, 0.1);
  EXPECT_EQ(c.sizing.size.le_size, 0.0);
  EXPECT_EQ(c.sizing.size.te_size, 0.0);
  EXPECT_DOUBLE_EQ(c.wake.direction[0], 1.0);  // x, in the wall plane y = 0
  EXPECT_DOUBLE_EQ(c.wake.direction[1], 0.0);
  // The sharp trailing edge ends among the tip's small faces (not all of them flat tips): it reaches
  // the tip, the H-type.
  EXPECT_EQ(c.nearfield.topology, "H");
}

// The near field init writes follows the trailing edge: a wing whose base runs from the root to
// the tip gets the H-type, whether the base is one face, split along the span into a lower and an
// upper half (as OpenVSP writes it), one face per panel of a cranked wing, or both (the summary
// says how many faces); a sharp edge of one curve too. A cranked sharp edge, whose trailing edge
// goes on from the root panel's curve into the next panel's, gets the C-type and the curve named
// (the H-type's wake block stands on one sharp curve; on the next panel's layer TetGen crashed).
// The files are written by tests/occ/write_wing_variant.
TEST(InitCommand, ABaseOfSeveralFacesGetsTheHTypeACrankedSharpEdgeTheCType) {
#ifndef SEMIMESH_WRITE_WING_VARIANT
  GTEST_SKIP() << "no occ backend: write_wing_variant is not built";
#else
  const std::filesystem::path dir = semimesh::test::temp_path("init_cranked");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  struct Case {
    const char* variant;
    const char* te;
    const char* topology;
    const char* says;
  };
  for (const Case& k : {Case{"capped", "blunt", "H", "has a trailing-edge base"},
                        Case{"capped", "sharp", "H", "a sharp trailing edge for the wake block"},
                        Case{"cranked", "blunt", "H", "of 2 faces forming one strip"},
                        Case{"split_base", "blunt", "H", "of 2 faces forming one strip"},
                        Case{"cranked_split_base", "blunt", "H", "of 4 faces forming one strip"},
                        Case{"cranked", "sharp", "C", "does not touch the root"}}) {
    const std::string name = std::string(k.variant) + "_" + k.te;
    const std::string step = (dir / (name + ".step")).string(), toml = (dir / (name + ".toml")).string();
    const std::string write = std::string(SEMIMESH_WRITE_WING_VARIANT) + " " + k.variant + " " + step +
                              " naca.farfield=false naca.span=1 naca.te=" + k.te + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(write.c_str()), 0) << write;
    std::ostringstream out, err;
    ASSERT_EQ(run_init_command({toml, false, step}, out, err), 0) << name << ": " << err.str();
    EXPECT_EQ(pipeline::load_config(toml).nearfield.topology, k.topology) << name;
    std::ifstream text(toml);
    const std::string written((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
    EXPECT_NE(written.find(k.says), std::string::npos) << name << ":\n" << written;
    // cad-info lists the same base faces by the same ids.
    const std::string from = "one strip from the root to the tip (", to = "), carries";
    if (const auto at = written.find(from); at != std::string::npos) {
      const std::string faces = written.substr(at + from.size(), written.find(to, at) - at - from.size());
      std::ostringstream info;
      run_cad_info(backends::default_registry(), CadInfoOptions{"", step, {}, false}, info);
      EXPECT_NE(info.str().find("te faces  " + faces + ": "), std::string::npos) << name << ": " << faces;
    }
  }
  std::filesystem::remove_all(dir);
#endif
}

// The trailing-edge base's faces (detail::trailing_edge_base) on OCC files (the analytic wing has
// one base face and cannot be split): one face, the two halves of a base split along the span, the
// two panels' bases of the cranked wing, the four of both; never a skin or the tip.
TEST(TrailingEdgeBase, GathersTheFacesOfASplitOrCrankedBase) {
#ifndef SEMIMESH_WRITE_WING_VARIANT
  GTEST_SKIP() << "no occ backend: write_wing_variant is not built";
#else
  const std::filesystem::path dir = semimesh::test::temp_path("te_base_faces");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const auto& [variant, count] : {std::pair<const char*, std::size_t>{"capped", 1}, {"split_base", 2},
                                       {"cranked", 2}, {"cranked_split_base", 4}}) {
    const std::string step = (dir / (std::string(variant) + ".step")).string();
    const std::string write = std::string(SEMIMESH_WRITE_WING_VARIANT) + " " + variant + " " + step +
                              " naca.farfield=false naca.span=1 > /dev/null 2>&1";
    ASSERT_EQ(std::system(write.c_str()), 0) << write;
    const ModelAsRun loaded = load_model_as_run(backends::default_registry(), "occ", step);
    const surface::CadRoles roles = surface::detect_cad_roles(*loaded.model);
    ASSERT_TRUE(roles.te_base) << variant;
    const nearfield::BodyRoles body{roles.body, roles.wall};
    const std::vector<int> faces = nearfield::detail::trailing_edge_base(*loaded.model, body, *roles.te_base);
    EXPECT_EQ(faces.size(), count) << variant;
    for (int s : faces) {  // narrow faces: the base's, not a skin's or the tip's
      EXPECT_LT(cad::face_area(loaded.model->surface(s)).area, 0.02) << variant << ": " << s;
      EXPECT_FALSE(std::count(roles.tip.begin(), roles.tip.end(), s)) << variant << ": " << s;
    }
    EXPECT_EQ(nearfield::detail::trailing_edge_continuation(*loaded.model, body, faces, -1), -1) << variant;
    const int other = faces.size() == 2 ? (faces[0] == *roles.te_base ? faces[1] : faces[0]) : -1;
    if (std::string(variant) == "cranked") {  // the root panel's base alone: it goes on into the other panel's
      EXPECT_EQ(nearfield::detail::trailing_edge_continuation(*loaded.model, body, {*roles.te_base}, -1), other);
    }
    if (std::string(variant) != "split_base") continue;
    // Without the tip among the body's faces (as on OpenVSP's M6, whose tip is slivers at the
    // trailing edge) both the upper skin and the other half border nothing else past the root's
    // half: the trailing edge goes on into the other half, and that is the face named.
    nearfield::BodyRoles no_tip = body;
    for (int t : roles.tip) no_tip.body_surfaces.erase(std::find(no_tip.body_surfaces.begin(), no_tip.body_surfaces.end(), t));
    EXPECT_EQ(nearfield::detail::trailing_edge_continuation(*loaded.model, no_tip, {*roles.te_base}, -1), other);
  }
  std::filesystem::remove_all(dir);
#endif
}

// The line of `text` that starts with `start` (empty when none).
std::string line_starting(const std::string& text, const std::string& start) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(start, 0) == 0) return line;
  return {};
}

// cad-info and init name every face by the id `run` uses: on a body-only file with a root cap the
// wall and a box are built at load, which renumbers the faces; cad-info listed the file's ids before
// (its base was surface 2, init's and run's surface 6).
TEST(InitCommand, CadInfoAndInitNameTheBaseByTheSameId) {
#ifndef SEMIMESH_WRITE_WING_VARIANT
  GTEST_SKIP() << "no occ backend: write_wing_variant is not built";
#else
  const std::filesystem::path dir = semimesh::test::temp_path("init_cad_info_ids");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string step = (dir / "wing.step").string(), toml = (dir / "wing.toml").string();
  const std::string write = std::string(SEMIMESH_WRITE_WING_VARIANT) + " capped " + step +
                            " naca.farfield=false naca.span=1 > /dev/null 2>&1";
  ASSERT_EQ(std::system(write.c_str()), 0) << write;
  std::ostringstream info, out, err;
  run_cad_info(backends::default_registry(), CadInfoOptions{"", step, {}, false}, info);
  ASSERT_EQ(run_init_command({toml, false, step}, out, err), 0) << err.str();
  std::ifstream text(toml);
  const std::string written((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
  const std::string base = line_starting(info.str(), "te_base   surface ");
  ASSERT_FALSE(base.empty()) << info.str();
  EXPECT_NE(written.find("# " + base + "\n"), std::string::npos) << "cad-info: " << base << "\ninit:\n" << written;
  const std::string wall = line_starting(info.str(), "wall      surface ");
  EXPECT_NE(written.find("# " + wall + "\n"), std::string::npos) << "cad-info: " << wall << "\ninit:\n" << written;
  // The id and the name a config entry uses are cad-info's.
  const pipeline::Config config = pipeline::load_config(toml);
  EXPECT_NE(base.find("'" + config.wake.te_base + "'"), std::string::npos) << base << " vs " << config.wake.te_base;
  std::filesystem::remove_all(dir);
#endif
}

}  // namespace
}  // namespace semimesh::app
