// Failures reach the user as CadErrors that name the vendor call, the file or entity, and the
// vendor's reason: missing file, bad file, unknown or malformed options, queries out of range.
#include "semimesh/vendor/vendor_backend.hpp"

#include "semimesh/cad/error.hpp"
#include "semimesh/cad/registry.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "temp_path.hpp"

namespace semimesh::vendor {
namespace {

using Kind = cad::CadError::Kind;
namespace fs = std::filesystem;

// A file in a per-process temporary folder, removed at the end of the test.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& content)
      : path_(semimesh::test::temp_path("vendor") / name) {
    fs::create_directories(path_.parent_path());
    std::ofstream(path_) << content;
  }
  ~TempFile() { fs::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

// Loads and returns the CadError it must throw.
cad::CadError load_error(const cad::Source& source) {
  try {
    load_vendor(source);
  } catch (const cad::CadError& e) {
    return e;
  }
  ADD_FAILURE() << "loading '" << source.path << "' did not throw";
  return cad::CadError(Kind::Geometry, "");
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

TEST(VendorLoad, MissingFileIsFileNotFoundNamingTheCallAndPath) {
  const std::string path = semimesh::test::temp_path("vendor_no_such_file.vcad").string();
  cad::CadError e = load_error({path, {}});
  EXPECT_EQ(e.kind(), Kind::FileNotFound);
  expect_contains(e.what(), "vc_model_load");
  expect_contains(e.what(), path);
  expect_contains(e.what(), "VC_ERR_FILE_NOT_FOUND");
}

TEST(VendorLoad, FileWithoutHeaderIsUnreadableNamingTheLine) {
  TempFile file("no_header.vcad", "# a comment\nnaca.code = 0012\n");
  cad::CadError e = load_error({file.path(), {}});
  EXPECT_EQ(e.kind(), Kind::FileUnreadable);
  expect_contains(e.what(), "VC_ERR_BAD_FILE");
  expect_contains(e.what(), "line 2");
}

TEST(VendorLoad, FileWithMalformedLineIsUnreadable) {
  TempFile file("malformed.vcad", "vcad 1\nnaca.code 0012\n");
  cad::CadError e = load_error({file.path(), {}});
  EXPECT_EQ(e.kind(), Kind::FileUnreadable);
  expect_contains(e.what(), "line 2");
}

TEST(VendorLoad, FileWithParameterTheGeneratorRejectsIsUnreadable) {
  TempFile file("bad_code.vcad", "vcad 1\nnaca.code = banana\n");
  cad::CadError e = load_error({file.path(), {}});
  EXPECT_EQ(e.kind(), Kind::FileUnreadable);
  expect_contains(e.what(), "naca.code");
}

TEST(VendorLoad, GoodFileLoads) {
  TempFile file("good.vcad", "# NACA 0012 wing\nvcad 1\n\nnaca.code = 0012\n");
  auto model = load_vendor({file.path(), {}});
  EXPECT_GT(model->num_surfaces(), 0);
  EXPECT_EQ(model->backend(), "vendor");
}

TEST(VendorLoad, UnknownOptionIsBadParameterNamingIt) {
  cad::CadError e = load_error({"naca:naca.code=0012", {{"colour", "red"}}});
  EXPECT_EQ(e.kind(), Kind::BadParameter);
  expect_contains(e.what(), "VC_ERR_UNKNOWN_OPTION");
  expect_contains(e.what(), "colour");
}

TEST(VendorLoad, MalformedOptionValueIsBadParameter) {
  cad::CadError e = load_error({"naca:naca.code=0012", {{"units", "furlong"}}});
  EXPECT_EQ(e.kind(), Kind::BadParameter);
  expect_contains(e.what(), "VC_ERR_BAD_PARAM");
  expect_contains(e.what(), "furlong");
}

TEST(VendorLoad, OptionThatCannotBeEncodedIsRejectedBeforeTheKernel) {
  cad::CadError e = load_error({"naca:naca.code=0012", {{"units", "mm;tolerance=1"}}});
  EXPECT_EQ(e.kind(), Kind::BadParameter);
  expect_contains(e.what(), "units");
}

TEST(VendorLoad, EmptyPathIsBadParameter) {
  cad::CadError e = load_error({"", {{"naca.code", "0012"}}});
  EXPECT_EQ(e.kind(), Kind::BadParameter);
  expect_contains(e.what(), "path");
}

TEST(VendorLoad, OptionsReachTheKernel) {
  auto model = load_vendor({"naca:naca.code=0012", {{"units", "mm"}, {"tolerance", "1e-5"}}});
  EXPECT_EQ(model->units(), "mm");
  EXPECT_EQ(model->scale_applied(), 1.0);
  EXPECT_EQ(model->tolerance(), 1e-5);
}

TEST(VendorLoad, ModelUnitComesFromTheKernel) {
  EXPECT_EQ(load_vendor({"naca:naca.units=mm", {}})->units(), "mm");
  EXPECT_EQ(load_vendor({"naca:naca.units=m", {}})->units(), "m");
  // The kernel has no unit "chord" (the generator's default label): it reports none.
  EXPECT_EQ(load_vendor({"naca:naca.code=0012", {}})->units(), "unknown");
}

TEST(VendorQuery, EvaluationOutsideTheRangeNamesCallEntityAndRange) {
  auto model = load_vendor({"naca:naca.code=0012", {}});
  const cad::Curve& curve = model->curve(0);
  cad::Interval range = curve.bounds();
  try {
    curve.derivatives(range.hi + 2.0 * range.length());
    FAIL() << "evaluation far outside the range did not throw";
  } catch (const cad::CadError& e) {
    EXPECT_EQ(e.kind(), Kind::Geometry);
    expect_contains(e.what(), "vc_edge_eval");
    expect_contains(e.what(), "VC_ERR_OUT_OF_RANGE");
    expect_contains(e.what(), "edge #");
    expect_contains(e.what(), "semimesh id 0");
    if (!curve.name().empty()) expect_contains(e.what(), "'" + curve.name() + "'");
  }
}

TEST(VendorRegistry, BackendInfoRegistersByNameAndExtension) {
  cad::BackendInfo info = backend_info();
  EXPECT_EQ(info.name, "vendor");
  EXPECT_EQ(info.extensions, std::vector<std::string>{".vcad"});
  cad::Registry registry;
  registry.add(info);
  EXPECT_TRUE(registry.available("vendor"));
  EXPECT_EQ(registry.backend_for_path("Wing.VCAD"), "vendor");
  auto model = registry.load("vendor", {"naca:naca.code=0012", {}});
  EXPECT_EQ(model->backend(), "vendor");
}

}  // namespace
}  // namespace semimesh::vendor
