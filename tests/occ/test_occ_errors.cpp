// Bad inputs: each gives a CadError of the right kind whose message names the file.
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepTools.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Edge.hxx>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "temp_path.hpp"

namespace semimesh::occ {
namespace {

using cad::CadError;

std::string temp_path(const std::string& name) {
  return semimesh::test::temp_path("occ_" + name).string();
}

/// Runs load_occ and returns the error it throws (fails the test when it throws nothing).
CadError load_error(const std::string& path, cad::Params params = {}) {
  try {
    load_occ(cad::Source{path, params});
  } catch (const CadError& error) {
    return error;
  }
  ADD_FAILURE() << "loading '" << path << "' did not throw";
  return CadError(CadError::Kind::Geometry, "");
}

TEST(OccErrors, MissingFileIsNamed) {
  const std::string path = temp_path("does_not_exist.step");
  const CadError error = load_error(path);
  EXPECT_EQ(error.kind(), CadError::Kind::FileNotFound);
  EXPECT_NE(std::string(error.what()).find("cannot open '" + path + "': no such file"), std::string::npos) << error.what();
}

TEST(OccErrors, CorruptStepIsUnreadable) {
  const std::string path = temp_path("garbage.stp");
  std::ofstream(path) << "this is not ISO-10303-21\n#1=PRODUCT(((;\n";
  const CadError error = load_error(path);
  std::remove(path.c_str());
  EXPECT_EQ(error.kind(), CadError::Kind::FileUnreadable);
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
}

TEST(OccErrors, StepWithoutFacesHasNoGeometry) {
  const std::string path = temp_path("edge_only.step");
  STEPControl_Writer writer;
  writer.Transfer(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), STEPControl_AsIs);
  ASSERT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);
  const CadError error = load_error(path);
  std::remove(path.c_str());
  EXPECT_EQ(error.kind(), CadError::Kind::NoGeometry);
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
}

TEST(OccErrors, BrepWithoutFacesHasNoGeometry) {
  const std::string path = temp_path("edge_only.brep");
  ASSERT_TRUE(BRepTools::Write(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), path.c_str()));
  const CadError error = load_error(path);
  std::remove(path.c_str());
  EXPECT_EQ(error.kind(), CadError::Kind::NoGeometry);
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
}

TEST(OccErrors, FileWithoutBrepHeaderIsUnreadable) {
  const std::string path = temp_path("not_topology.brep");
  std::ofstream(path) << "solid cube\nendsolid\n";
  const CadError error = load_error(path);
  std::remove(path.c_str());
  EXPECT_EQ(error.kind(), CadError::Kind::FileUnreadable);
  EXPECT_NE(std::string(error.what()).find("not a BREP file"), std::string::npos) << error.what();
}

// OCC's readers report through its default messenger, which prints to stdout; a `--json`
// consumer of the CLI must see nothing but our output, so loading prints nothing at all.
TEST(OccErrors, LoadingPrintsNothing) {
  const std::string corrupt = temp_path("noisy.stp"), empty = temp_path("empty.brep"), good = temp_path("edge.step");
  std::ofstream(corrupt) << "ISO-10303-21;\nHEADER;\nthis is not a STEP file at all ((((\n";
  std::ofstream(empty).flush();
  STEPControl_Writer writer;
  writer.Transfer(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), STEPControl_AsIs);
  ASSERT_EQ(writer.Write(good.c_str()), IFSelect_RetDone);
  testing::internal::CaptureStdout();
  for (const std::string& path : {corrupt, empty, good}) {
    try {
      load_occ(cad::Source{path, {}});
    } catch (const CadError&) {
      // expected for all three; only the output matters here
    }
  }
  const std::string printed = testing::internal::GetCapturedStdout();
  for (const std::string& path : {corrupt, empty, good}) std::remove(path.c_str());
  EXPECT_EQ(printed, "");
}

TEST(OccErrors, UnknownExtensionIsNamed) {
  const CadError error = load_error("wing.xyz");
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("'wing.xyz'"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find(".xyz"), std::string::npos) << error.what();
}

TEST(OccErrors, UnknownParameterIsNamed) {
  const std::string path = temp_path("box.brep");
  const CadError error = load_error(path, {{"occ.scael", "2"}});
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("occ.scael"), std::string::npos) << error.what();
}

TEST(OccErrors, NonPositiveScaleIsRejected) {
  const CadError error = load_error("", {{"occ.scale", "-1"}});
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("occ.scale"), std::string::npos) << error.what();
}

// The generated B-spline wing has a flat tip: a rounded one (the analytic backend's) is refused by
// name, not silently built flat.
TEST(OccErrors, RoundTipOfTheGeneratedWingIsRefused) {
  const CadError error = load_error("", {{"naca.tip", "round"}});
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("naca.tip"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find("flat tip"), std::string::npos) << error.what();
}

// ... and so is the analytic backend's fuselage.
TEST(OccErrors, CylinderWallOfTheGeneratedWingIsRefused) {
  const CadError error = load_error("", {{"naca.wall", "cylinder"}});
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("naca.wall"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find("plane"), std::string::npos) << error.what();
}

TEST(OccErrors, DihedralOfTheGeneratedWingIsRefused) {
  const CadError error = load_error("", {{"naca.dihedral", "5"}});
  EXPECT_EQ(error.kind(), CadError::Kind::BadParameter);
  EXPECT_NE(std::string(error.what()).find("naca.dihedral"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace semimesh::occ
