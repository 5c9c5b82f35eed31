// End-to-end `run` on a coarse NACA 0012 case (order 1 and order 2, a few thousand elements) and
// the comparison of the analytic and OCC-built wings.
#include "semimesh/pipeline/pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include "temp_path.hpp"

namespace semimesh::pipeline {
namespace {

namespace fs = std::filesystem;

class CountingProgress : public Progress {
 public:
  void stage_started(const std::string& name) override { started.push_back(name); }
  void stage_finished(const StageTiming& timing) override { finished.push_back(timing.name); }
  void stage_progress(double fraction, const std::string&) override { fractions[started.back()].push_back(fraction); }
  std::vector<std::string> started, finished;
  std::map<std::string, std::vector<double>> fractions;  ///< stage -> its progress reports
};

// The CLI tests' coarse case (tests/pipeline/coarse_wing.toml: unit span, 7 x 6 x 3 chord box,
// 0.05 chord shell), writing the three solver formats unless `overrides` say otherwise.
Config coarse_config(const fs::path& directory, const std::vector<std::string>& overrides = {}) {
  std::vector<std::string> all = {"output.formats=[\"msh41\", \"vtu\", \"nektar\"]"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  Config c = load_config(std::string(SEMIMESH_SOURCE_DIR) + "/tests/pipeline/coarse_wing.toml", all);
  c.output.directory = directory.string();
  return c;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The number after "key": in a JSON text (the first occurrence); NaN when absent.
double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": (-?[0-9.]+(e[-+]?[0-9]+)?)")))
    return std::nan("");
  return std::stod(m[1].str());
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = semimesh::test::temp_path("pipeline_" + name);
  fs::remove_all(dir);
  return dir;
}

TEST(PipelineRun, CoarseWingIsAValidConformingHybridMesh) {
  const fs::path dir = fresh_directory("coarse");
  CountingProgress progress;
  const RunResult r = run(coarse_config(dir), progress);

  EXPECT_EQ(progress.started, progress.finished);
  EXPECT_GE(progress.finished.size(), 7u);
  EXPECT_GT(r.elements_by_type.at("prism"), 100u);
  EXPECT_GT(r.elements_by_type.at("tetrahedron"), 1000u);
  EXPECT_LT(r.mesh.elements().size(), 50000u);
  for (const char* group : {"wing", "wall", "farfield"}) EXPECT_GT(r.boundary_faces_by_group.count(group), 0u) << group;

  EXPECT_EQ(r.validity.invalid, 0u);
  EXPECT_GT(r.validity.min_scaled_jacobian, 0.0);
  EXPECT_TRUE(r.conformity.ok()) << r.conformity.problems.front().describe(r.mesh);
  EXPECT_LT(r.volume.mesh.boundary_relative_error(), 1e-10);
  EXPECT_LT(r.volume.expected_relative_error(), 1e-8);
  // Box 7 x 6 x 3 = 126 minus a NACA 0012 wing of unit chord and span (section area 0.0822).
  EXPECT_NEAR(r.volume.box_volume, 126.0, 1e-9);
  EXPECT_NEAR(r.volume.body_volume, 0.0822, 0.002);
  EXPECT_TRUE(r.checks_passed());

  ASSERT_EQ(r.written_files.size(), 4u);
  for (const char* name : {"coarse.msh", "coarse.vtu", "coarse.xml", "report.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
  for (const auto& entry : fs::directory_iterator(dir))  // no temporary file left behind
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();

  std::ifstream report(dir / "report.json");
  std::stringstream text;
  text << report.rdbuf();
  EXPECT_NE(text.str().find("\"invalid_elements\": 0"), std::string::npos);
  EXPECT_NE(text.str().find("\"checks_passed\": true"), std::string::npos);
  fs::remove_all(dir);
}

// run() stages the mesh files while its conformity check ends and keeps them only when it passes:
// write_outputs makes that decision on the result it is given. A result with a conformity problem
// leaves the folder as it was (an earlier file kept, nothing added), unless invalid meshes are allowed.
TEST(PipelineRun, AResultThatFailedItsConformityCheckIsWrittenOnlyWhenInvalidMeshesAreAllowed) {
  CountingProgress progress;
  const fs::path dir = fresh_directory("conformity_failed");
  Config config = coarse_config(dir, {"output.formats=[\"msh41\"]"});
  RunResult r = run(config, progress);
  ASSERT_TRUE(r.checks_passed());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "keep.txt") << "an earlier result\n";
  r.conformity.problems.emplace_back();
  r.written_files.clear();
  write_outputs(config, progress, r);
  EXPECT_TRUE(r.written_files.empty());
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"keep.txt"});

  config.output.allow_invalid = true;
  write_outputs(config, progress, r);
  EXPECT_EQ(r.written_files.size(), 2u);
  EXPECT_TRUE(fs::is_regular_file(dir / "coarse.msh"));
  EXPECT_NE(read_text(dir / "report.json").find("\"checks_passed\": false"), std::string::npos);
  fs::remove_all(dir);
}

// A caller that reads no position after the run may keep the mesh as written: the same files,
// and a mesh that says what it is (equispaced nodes of the same maps, no CAD attachments), where
// the default gives back the mesh as made.
TEST(PipelineRun, TheMeshAsWrittenIsTheFilesMeshAndTheFilesAreTheSame) {
  CountingProgress progress;
  const fs::path made_dir = fresh_directory("as_meshed"), written_dir = fresh_directory("as_written");
  const std::vector<std::string> order3 = {"highorder.order=3", "output.pictures=true"};
  const RunResult made = run(coarse_config(made_dir, order3), progress);
  const RunResult written = run(coarse_config(written_dir, order3), progress, MeshAfterWrite::AsWritten);
  ASSERT_TRUE(made.checks_passed() && written.checks_passed());
  ASSERT_EQ(made.written_files.size(), written.written_files.size());
  for (const std::string& file : made.written_files) {
    const std::string name = fs::path(file).filename().string();
    if (name == "report.json") continue;  // its timings differ
    EXPECT_EQ(read_text(made_dir / name), read_text(written_dir / name)) << name;
  }
  EXPECT_EQ(made.mesh.node_set(), ho::NodeSet::GLL);
  EXPECT_EQ(written.mesh.node_set(), ho::NodeSet::Equispaced);
  std::size_t attached = 0;
  for (mesh::NodeId i = 0; i < made.mesh.num_nodes(); ++i) {
    attached += made.mesh.cad_attachment(i).kind != mesh::CadAttachment::None;
    ASSERT_EQ(written.mesh.cad_attachment(i).kind, mesh::CadAttachment::None) << i;
  }
  EXPECT_GT(attached, 0u);
  // Vertices are not resampled; the other nodes moved from the GLL to the equispaced places.
  ASSERT_EQ(written.mesh.num_nodes(), made.mesh.num_nodes());
  std::size_t moved = 0;
  for (mesh::NodeId i = 0; i < made.mesh.num_nodes(); ++i) moved += written.mesh.node(i) != made.mesh.node(i);
  EXPECT_GT(moved, made.mesh.num_nodes() / 2);
  for (std::size_t e = 0; e < made.mesh.elements().size(); ++e)
    for (int v = 0; v < ho::num_vertices(made.mesh.elements()[e].shape); ++v) {
      const mesh::NodeId id = made.mesh.elements()[e].vertices[v];
      ASSERT_EQ(written.mesh.node(id), made.mesh.node(id)) << "vertex " << id;
    }
  fs::remove_all(made_dir);
  fs::remove_all(written_dir);
}

// Order 2, shell split into 3 layers of ratio 2, against the same case at order 1 without a split.
TEST(PipelineRun, CoarseWingAtOrderTwoWithThreeLayers) {
  CountingProgress progress;
  const fs::path linear_dir = fresh_directory("linear_one_layer");
  const RunResult linear =
      run(coarse_config(linear_dir, {"boundary_layer.layers=1", "output.formats=[\"msh41\"]"}), progress);
  const fs::path dir = fresh_directory("order2");
  progress.fractions.clear();  // the reports of this run only
  const RunResult r = run(coarse_config(dir, {"highorder.order=2", "boundary_layer.layers=3",
                                              "boundary_layer.ratio=2", "output.formats=[\"msh41\"]"}),
                          progress);

  EXPECT_NE(std::find(progress.finished.begin(), progress.finished.end(), "curve"), progress.finished.end());
  EXPECT_NE(std::find(progress.finished.begin(), progress.finished.end(), "repair"), progress.finished.end());
  EXPECT_NE(std::find(progress.finished.begin(), progress.finished.end(), "split"), progress.finished.end());
  // At order 2 the size field computes the shell's limits on the curved body faces, the bulk of
  // that stage: it reports its progress, non-decreasing, up to 0.9 at least.
  const std::vector<double>& size_field = progress.fractions["size field"];
  ASSERT_GE(size_field.size(), 3u);
  EXPECT_TRUE(std::is_sorted(size_field.begin(), size_field.end()));
  EXPECT_GE(size_field.back(), 0.9);
  EXPECT_EQ(r.mesh.order(), 2);
  EXPECT_EQ(r.validity.invalid, 0u);
  EXPECT_GT(r.validity.min_scaled_jacobian, 0.0);
  EXPECT_TRUE(r.conformity.ok()) << r.conformity.problems.front().describe(r.mesh);
  EXPECT_TRUE(r.checks_passed());
  EXPECT_EQ(r.elements_by_type.at("prism"), 3 * linear.elements_by_type.at("prism"));
  EXPECT_EQ(r.elements_by_type.at("tetrahedron"), linear.elements_by_type.at("tetrahedron"));
  for (const char* group : {"wing", "wall", "farfield"}) EXPECT_GT(r.boundary_faces_by_group.count(group), 0u) << group;
  EXPECT_EQ(r.boundary_faces_by_group.at("wing"), linear.boundary_faces_by_group.at("wing"));

  // Curving brings the wing's faces onto the CAD: the error must drop well below the linear one.
  EXPECT_GT(linear.geometric_error.max_rel, 0.0);
  EXPECT_LT(r.geometric_error.max_rel, 0.5 * linear.geometric_error.max_rel);
  EXPECT_LT(r.geometric_error.rms_rel, linear.geometric_error.rms_rel);

  // Layers 1 : 2 : 4 of the 0.05 shell: the first cell is 0.05 / 7 where the shell is not thinned.
  EXPECT_EQ(r.layers.layers, 3);
  EXPECT_NEAR(r.layers.achieved_ratio, 2.0, 0.05);
  EXPECT_NEAR(r.layers.first_cell_height_max, 0.05 / 7.0, 0.05 / 7.0 * 0.05);
  EXPECT_GT(r.layers.first_cell_height_min, 0.0);
  EXPECT_LE(r.layers.first_cell_height_min, r.layers.first_cell_height_max);
  EXPECT_GT(r.layers.max_first_layer_aspect, 1.0);

  const std::string report = read_text(dir / "report.json");
  for (const char* key : {"\"order\": 2", "\"layers\": 3", "\"first_cell_height_min\"", "\"first_cell_height_max\"",
                          "\"achieved_layer_ratio\"", "\"max_first_layer_aspect_ratio\"", "\"geometric_error\"",
                          "\"max_rel\"", "\"rms_rel\"", "\"invalid_elements\": 0"})
    EXPECT_NE(report.find(key), std::string::npos) << key;
  fs::remove_all(linear_dir);
  fs::remove_all(dir);
}

// The paper's spring optimisation is selectable and yields a valid mesh with every edge and face
// converged; the default parameter placement is far more accurate on this wing (docs/config.md).
TEST(PipelineRun, SpringPlacementIsValidButLessAccurateThanParameterPlacement) {
  CountingProgress progress;
  const fs::path dir = fresh_directory("springs");
  const std::vector<std::string> common{"highorder.order=3", "boundary_layer.layers=2", "output.formats=[\"msh41\"]"};
  std::vector<std::string> springs = common;
  springs.push_back("highorder.node_placement=springs");
  const RunResult by_parameter = run(coarse_config(dir, common), progress);
  const RunResult by_springs = run(coarse_config(dir, springs), progress);

  EXPECT_EQ(by_parameter.node_placement, "parameter");
  EXPECT_EQ(by_springs.node_placement, "springs");
  EXPECT_TRUE(by_springs.checks_passed());
  EXPECT_EQ(by_springs.validity.invalid, 0u);
  EXPECT_EQ(by_springs.curving.optimisation_fallbacks, 0);
  EXPECT_GT(by_springs.curving.faces_on_surfaces, 0);
  EXPECT_EQ(by_springs.curving.faces_on_surfaces, by_parameter.curving.faces_on_surfaces);
  // Springs move interior nodes along the surface, so the meshes differ, and the jitter between
  // edge and face placements costs accuracy (measured: ~1000x at order 4 on this case).
  EXPECT_GT(by_springs.geometric_error.max_rel, 10.0 * by_parameter.geometric_error.max_rel);
  const std::string report = read_text(dir / "report.json");
  EXPECT_NE(report.find("\"node_placement\": \"springs\""), std::string::npos);
  EXPECT_NE(report.find("\"spring_fallbacks\": 0"), std::string::npos);
  fs::remove_all(dir);
}

// boundary_layer.ratio_line: r = 2 at the root (z = 0), 1 at the tip (z = 1 = span); the first
// cell is 0.05 / 7 at the root (1 : 2 : 4) and 0.05 / 3 at the tip (three equal layers).
TEST(PipelineRun, RatioVaryingAlongTheSpan) {
  CountingProgress progress;
  const fs::path dir = fresh_directory("ratio_line");
  const RunResult r = run(coarse_config(dir, {"boundary_layer.layers=3", "boundary_layer.ratio=2",
                                              "boundary_layer.ratio_line=[0, 0, 0, 0, 0, 1]",
                                              "boundary_layer.ratio_end=1", "output.formats=[\"msh41\"]"}),
                          progress);
  EXPECT_TRUE(r.checks_passed());
  EXPECT_NEAR(r.layers.first_cell_height_min, 0.05 / 7.0, 0.05 / 7.0 * 0.02);
  EXPECT_NEAR(r.layers.first_cell_height_max, 0.05 / 3.0, 0.05 / 3.0 * 0.02);
  EXPECT_EQ(r.layers.requested_ratio, 2.0);
  EXPECT_EQ(r.layers.requested_ratio_end, 1.0);
  EXPECT_GT(r.layers.achieved_ratio, 1.0);
  EXPECT_LT(r.layers.achieved_ratio, 2.0);

  // What a user reads: report.json carries the same figures, each under its own name. At the root
  // (r = 2) the three layers are 1 + 2 + 4 first cells of a 0.05 shell, at the tip (r = 1) three.
  ASSERT_NEAR(r.thickness_min, r.thickness_max, 1e-12);  // no local reduction, so the closed forms hold
  const std::string report = read_text(dir / "report.json");
  EXPECT_NEAR(json_number(report, "first_cell_height_min"), 0.05 / 7.0, 0.05 / 7.0 * 0.02) << report;
  EXPECT_NEAR(json_number(report, "first_cell_height_max"), 0.05 / 3.0, 0.05 / 3.0 * 0.02) << report;
  EXPECT_EQ(json_number(report, "layers"), 3.0);
  EXPECT_EQ(json_number(report, "layer_ratio"), 2.0);
  EXPECT_EQ(json_number(report, "layer_ratio_end"), 1.0);
  EXPECT_EQ(json_number(report, "elements"), static_cast<double>(r.mesh.elements().size()));
  EXPECT_EQ(json_number(report, "invalid_elements"), 0.0);
  fs::remove_all(dir);
}

// y+ = 30 at Re = 1e6 on the unit chord: h = 30 / (1e6 sqrt(Cf / 2)), Cf = 0.026 Re^(-1/7), by hand
// 30 / (1e6 x 0.04250111) = 7.058640e-4; the four layers of the 0.05 shell then grow by r from it.
TEST(PipelineRun, FirstCellFromYPlus) {
  CountingProgress progress;
  const fs::path dir = fresh_directory("y_plus");
  const RunResult r = run(coarse_config(dir, {"boundary_layer.layers=4", "boundary_layer.y_plus=30",
                                              "boundary_layer.reynolds=1e6", "output.formats=[\"msh41\"]"}),
                          progress);
  ASSERT_TRUE(r.checks_passed());
  ASSERT_NEAR(r.thickness_min, r.thickness_max, 1e-12);
  EXPECT_NEAR(r.layers.first_cell_height_min, 7.058640e-4, 7.058640e-4 * 1e-6);
  EXPECT_NEAR(r.layers.first_cell_height_target, 7.058640e-4, 1e-10);
  EXPECT_NEAR(r.layers.y_plus_min, 30.0, 1e-4);
  const double q = r.layers.requested_ratio;  // h (q^4 - 1) / (q - 1) = 0.05
  EXPECT_NEAR(7.058640e-4 * (std::pow(q, 4) - 1) / (q - 1), 0.05, 1e-8);
  const std::string report = read_text(dir / "report.json");
  EXPECT_NEAR(json_number(report, "y_plus_min"), 30.0, 1e-4) << report;
  fs::remove_all(dir);
}

TEST(PipelineRun, BadInputIsReportedAsSuch) {
  const fs::path dir = fresh_directory("bad");
  CountingProgress progress;
  try {
    run(coarse_config(dir, {"geometry.body=[\"upper\", \"lower\", \"fin\"]"}), progress);
    ADD_FAILURE() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_EQ(e.cause(), Error::Cause::BadInput);
    EXPECT_NE(std::string(e.what()).find("geometry.body"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'fin'"), std::string::npos) << e.what();
  }
  try {
    run(coarse_config(dir, {"geometry.backend=parasolid"}), progress);
    ADD_FAILURE() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_EQ(e.cause(), Error::Cause::BadInput);
    EXPECT_EQ(e.stage(), "load CAD");
  }
  EXPECT_FALSE(fs::exists(dir));  // nothing written
}

// Every file of a run replaces an earlier run's together or not at all: the .msh is written
// before the .vtu fails, yet the older .msh stays byte for byte and no staging folder is left.
TEST(PipelineRun, AFailedWriteLeavesTheFolderAsItWas) {
  const fs::path dir = fresh_directory("failed_write");
  fs::create_directories(dir / "coarse.vtu" / "inside");  // a folder where the .vtu should go
  std::ofstream(dir / "older.txt") << "from another run\n";
  std::ofstream(dir / "coarse.msh") << "an older mesh\n";
  CountingProgress progress;
  try {
    run(coarse_config(dir, {"output.formats=[\"msh41\", \"vtu\"]"}), progress);
    ADD_FAILURE() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("coarse.vtu"), std::string::npos) << e.what();
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"coarse.msh", "coarse.vtu", "older.txt"}));
  std::ifstream msh(dir / "coarse.msh");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(msh), {}), "an older mesh\n");
  EXPECT_TRUE(fs::exists(dir / "coarse.vtu" / "inside"));
  fs::remove_all(dir);
}

TEST(PipelineRun, OutputPathsFollowTheFormats) {
  OutputConfig o;
  o.directory = "out";
  o.basename = "w";
  o.formats = {"msh41", "msh22", "vtu", "nektar"};
  EXPECT_EQ(output_paths(o), (std::vector<std::string>{"out/w.msh", "out/w.v22.msh", "out/w.vtu", "out/w.xml", "out/report.json"}));
  o.formats = {"msh22"};
  EXPECT_EQ(output_paths(o), (std::vector<std::string>{"out/w.msh", "out/report.json"}));
}

// Uniform sizes (no curvature or named-curve sources, which the OCC model lacks): the analytic
// and the OCC B-spline wing must give the same mesh: the same surface meshes and near field
// element for element, vertex for vertex. Not the same tetrahedra: TetGen's refinement turns
// the round-off between the two (the B-spline matches the closed form to ~1e-9 here) into a few
// different Steiner points (measured: 2956 and 2931 tetrahedra on boundaries equal to 4e-10),
// so the far field must only be as large to within 5 %.
TEST(PipelineRun, AnalyticAndOccWingsGiveTheSameMesh) {
  const std::vector<std::string> uniform = {"sizing.le_size=0", "sizing.te_size=0", "sizing.curvature_segments=0",
                                            "sizing.max_size=0.3", "geometry.naca.box=[-2,-2,0,3,2,2]",
                                            "farfield.box_size=0.6", "output.formats=[\"msh41\"]"};
  CountingProgress progress;
  std::vector<std::string> occ = uniform;
  occ.push_back("geometry.backend=occ");
  const RunResult a = run(coarse_config(fresh_directory("naca"), uniform), progress);
  const RunResult b = run(coarse_config(fresh_directory("occ"), occ), progress);
  const auto tets = [](const RunResult& r) { return r.elements_by_type.at("tetrahedron"); };
  EXPECT_NEAR(tets(a), tets(b), 0.05 * tets(a));
  for (const auto& [type, count] : a.elements_by_type) {
    if (type != "tetrahedron") {  // braces: EXPECT_* expand to an if-else (-Wdangling-else)
      EXPECT_EQ(b.elements_by_type.at(type), count) << type;
    }
  }
  // Vertices of the near field (every element that is not a tetrahedron) and of the boundary faces,
  // in the order both runs build them.
  const auto shaped_vertices = [](const mesh::Mesh& m) {
    std::vector<cad::Vec3> out;
    for (const mesh::Element& e : m.elements())
      if (e.shape != ho::Shape::Tetrahedron)
        for (int k = 0; k < ho::num_vertices(e.shape); ++k) out.push_back(m.node(e.vertices[k]));
    for (const mesh::BoundaryFace& f : m.boundary_faces())
      for (int k = 0; k < ho::num_vertices(f.shape); ++k) out.push_back(m.node(f.vertices[k]));
    return out;
  };
  const std::vector<cad::Vec3> va = shaped_vertices(a.mesh), vb = shaped_vertices(b.mesh);
  ASSERT_EQ(va.size(), vb.size());
  ASSERT_GT(va.size(), 1000u);
  double worst = 0.0;
  for (std::size_t k = 0; k < va.size(); ++k) worst = std::max(worst, (va[k] - vb[k]).norm());
  EXPECT_LT(worst, 1e-6);  // chord = 1
  fs::remove_all(fresh_directory("naca"));
  fs::remove_all(fresh_directory("occ"));
}

}  // namespace
}  // namespace semimesh::pipeline

namespace semimesh::pipeline {
namespace {

// topology "C" with a wall layer of thickness 0 is a slip wall: the very O-type mesh.
TEST(PipelineRunCType, SlipWallIsTheOTypeMesh) {
  CountingProgress progress;
  const RunResult o = run(coarse_config(fresh_directory("slip_o"), {"output.formats=[\"msh41\"]"}), progress);
  const RunResult c = run(coarse_config(fresh_directory("slip_c"), {"output.formats=[\"msh41\"]", "nearfield.topology=C",
                                                                   "wall_layer.thickness=0"}),
                          progress);
  ASSERT_EQ(o.mesh.num_nodes(), c.mesh.num_nodes());
  ASSERT_EQ(o.mesh.elements().size(), c.mesh.elements().size());
  EXPECT_TRUE(o.mesh.nodes() == c.mesh.nodes());
  for (std::size_t e = 0; e < o.mesh.elements().size(); ++e)
    ASSERT_EQ(o.mesh.element_nodes(e), c.mesh.element_nodes(e)) << "element " << e;
  EXPECT_EQ(c.junction_hexes, 0);
}

// The C-type at order 2: every check passes, the report has the regions, the junction and the
// first-cell heights of both layers (h1 = delta (r - 1) / (r^N - 1) on flat parts).
TEST(PipelineRunCType, OrderTwoReportsRegionsAndBothLayers) {
  const fs::path dir = fresh_directory("c_type");
  CountingProgress progress;
  const RunResult r = run(coarse_config(dir, {"nearfield.topology=C", "wall_layer.thickness=0.04", "wall_layer.layers=3",
                                              "wall_layer.ratio=1.5", "highorder.order=2", "boundary_layer.layers=3",
                                              "output.formats=[\"msh41\"]"}),
                          progress);
  EXPECT_TRUE(r.checks_passed());
  EXPECT_LT(r.geometric_error.max_rel, 1e-4);  // every boundary face, the hexes' wing and wall quads included
  EXPECT_GT(r.junction_hexes, 10);
  EXPECT_EQ(r.elements_by_region.at("junction"), static_cast<std::size_t>(r.junction_hexes * 3 * 3));
  EXPECT_EQ(r.elements_by_type.at("hexahedron"), r.elements_by_region.at("junction"));
  EXPECT_GT(r.elements_by_region.at("wall_layer"), 0u);
  EXPECT_GT(r.elements_by_region.at("wing_layer"), 0u);
  for (const char* region : {"junction", "wall_layer", "wing_layer", "farfield"})
    EXPECT_GT(r.validity.min_scaled_jacobian_by_region.at(region), 0.0) << region;
  const double wall_h1 = 0.04 * 0.5 / (1.5 * 1.5 * 1.5 - 1.0);
  EXPECT_NEAR(r.wall_layers.first_cell_height_min, wall_h1, 1e-3 * wall_h1);
  EXPECT_NEAR(r.wall_layers.first_cell_height_max, wall_h1, 1e-2 * wall_h1);
  std::ifstream report(dir / "report.json");
  std::stringstream text;
  text << report.rdbuf();
  for (const char* key : {"\"elements_by_region\"", "\"junction_hexes\"", "\"wall_layer\"", "\"min_scaled_jacobian_by_region\""})
    EXPECT_NE(text.str().find(key), std::string::npos) << key;
}

// wall_layer.ratio_line: the wall ratio 1.5 at the box's upstream side (x = -3), 1 at its downstream
// side (x = 4): the wall's first cell is 0.04 x 0.5 / (1.5^3 - 1) at the upstream box corners and
// 0.04 / 3 at the downstream ones; the junction hexes, split across the wall with the ratios of
// their wall feet, still conform to the wall prisms (checks passed) and are valid.
TEST(PipelineRunCType, WallRatioVaryingAlongTheWall) {
  const fs::path dir = fresh_directory("c_type_wall_ratio_line");
  CountingProgress progress;
  const RunResult r = run(coarse_config(dir, {"nearfield.topology=C", "wall_layer.thickness=0.04", "wall_layer.layers=3",
                                              "wall_layer.ratio=1.5", "wall_layer.ratio_line=[-3, 0, 0, 4, 0, 0]",
                                              "wall_layer.ratio_end=1", "highorder.order=2", "boundary_layer.layers=2",
                                              "output.formats=[\"msh41\"]"}),
                          progress);
  EXPECT_TRUE(r.checks_passed());
  EXPECT_TRUE(r.conformity.ok());
  EXPECT_GT(r.validity.min_scaled_jacobian_by_region.at("junction"), 0.0);
  const double upstream_h1 = 0.04 * 0.5 / (1.5 * 1.5 * 1.5 - 1.0), downstream_h1 = 0.04 / 3.0;
  EXPECT_NEAR(r.wall_layers.first_cell_height_min, upstream_h1, 1e-9);
  EXPECT_NEAR(r.wall_layers.first_cell_height_max, downstream_h1, 1e-9);
  EXPECT_EQ(r.wall_layers.requested_ratio, 1.5);
  EXPECT_EQ(r.wall_layers.requested_ratio_end, 1.0);
  fs::remove_all(dir);
}

// Bad C-type input: a BadInput RunError naming the entity and value, and no file written.
TEST(PipelineRunCType, BadInputNamesTheEntityAndWritesNothing) {
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{"nearfield.junction_min_angle=100"}, {"('root_", "90 degrees"}},
      {{"geometry.wall=upper", "geometry.body=[\"lower\", \"te_base\", \"tip\"]"}, {"('upper')", "no inner loop"}},
      {{"wall_layer.thickness=0.6"}, {"0.6", "wall layer"}},
      {{"geometry.naca.chord=0.05", "geometry.naca.te=sharp", "nearfield.thickness=0.6"},
       {"root loop is too short", "('root_", "thickness 0.6", "wall layer thickness 0.04",
        "(neighbouring prisms would fold"}},
      {{"geometry.naca.sweep=30", "geometry.naca.taper=0.5", "wall_layer.thickness=0.2"},
       {"thicker than the wing's shell", "('root_"}},
  };
  for (const auto& [overrides, expected] : cases) {
    const fs::path dir = fresh_directory("c_bad");
    std::vector<std::string> all = {"nearfield.topology=C", "wall_layer.thickness=0.04"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    CountingProgress progress;
    try {
      run(coarse_config(dir, all), progress);
      ADD_FAILURE() << "no RunError for " << overrides.front();
    } catch (const RunError& e) {
      EXPECT_EQ(e.cause(), Error::Cause::BadInput) << e.what();
      for (const std::string& part : expected) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir)) << overrides.front();
  }
}

}  // namespace
}  // namespace semimesh::pipeline

namespace semimesh::pipeline {
namespace {

// The generated wing through geometry.wall_plane and geometry.farfield = {box}: the wall z = 0 and
// the box cut at it are the wing's own wall and box, so the mesh is the one of naca.box.
TEST(PipelineRun, AGeneratedWingTakesTheWallPlaneAndFarFieldBox) {
  const fs::path dir = fresh_directory("wall_plane");
  Progress quiet;
  const RunResult own = run(coarse_config(dir / "own", {"output.formats=[\"msh41\"]"}), quiet);
  const RunResult from_keys = run(coarse_config(dir / "keys", {"output.formats=[\"msh41\"]",
                                                               "geometry.wall_plane.point=[0, 0, 0]",
                                                               "geometry.wall_plane.normal=[0, 0, 1]",
                                                               "geometry.farfield.box=[-3, -3, -1, 4, 3, 3]"}),
                                  quiet);
  EXPECT_TRUE(from_keys.checks_passed());
  EXPECT_EQ(from_keys.elements_by_type, own.elements_by_type);
  EXPECT_EQ(from_keys.volume.expected_volume(), own.volume.expected_volume());
  // box_chords: 1 chord around the wing's box [0, 1] x [-0.5, 0.5] x [0, 1] (the section's
  // half-chord bound on y): [-1, 2] x [-1.5, 1.5] x [0, 2], volume 18 minus the wing's.
  const RunResult chords = run(coarse_config(dir / "chords", {"output.formats=[\"msh41\"]",
                                                              "geometry.wall_plane.point=[0, 0, 0]",
                                                              "geometry.wall_plane.normal=[0, 0, 1]",
                                                              "geometry.farfield.box_chords=1"}),
                               quiet);
  EXPECT_TRUE(chords.checks_passed());
  EXPECT_NEAR(chords.volume.box_volume, 18.0, 1e-9);
  fs::remove_all(dir);
}

// geometry.naca.wall = "cylinder" reaches the analytic backend with its radius (and a dihedral with it); a box left at the
// plane's default (zmin = 0, inside the fuselage) is not passed, so the backend's box around the
// cylinder applies; a box given is passed as it is.
TEST(PipelineRun, ACylinderWallReachesTheBackend) {
  GeometryConfig g;
  EXPECT_FALSE(cad_source(g).params.has("naca.wall"));
  EXPECT_TRUE(cad_source(g).params.has("naca.box"));
  g.naca.wall = "cylinder";
  g.naca.wall_radius = 2.0;
  const cad::Params fuselage = cad_source(g).params;
  EXPECT_EQ(fuselage.get_string("naca.wall", ""), "cylinder");
  EXPECT_EQ(fuselage.get_double("naca.wall_radius", 0.0), 2.0);
  EXPECT_FALSE(fuselage.has("naca.box"));
  g.naca.box = {-5, -4, -6, 6, 4, 5};
  EXPECT_EQ(cad_source(g).params.get_string("naca.box", ""), "-5,-4,-6,6,4,5");
  EXPECT_FALSE(cad_source(g).params.has("naca.wall_angle"));
  g.naca.wall = "cone";
  g.naca.wall_angle = -2.5;
  EXPECT_EQ(cad_source(g).params.get_double("naca.wall_angle", 0.0), -2.5);
  EXPECT_FALSE(cad_source(g).params.has("naca.dihedral"));
  g.naca.dihedral = 12.5;
  EXPECT_EQ(cad_source(g).params.get_double("naca.dihedral", 0.0), 12.5);
}

}  // namespace
}  // namespace semimesh::pipeline
