// Params' typed getters and the backend Registry's lookups and messages.
#include "expect_error.hpp"

#include "semimesh/cad/registry.hpp"

#include <gtest/gtest.h>

using semimesh::cad::BackendInfo;
using semimesh::cad::CadError;
using semimesh::cad::Model;
using semimesh::cad::Params;
using semimesh::cad::Registry;
using semimesh::cad::Source;

TEST(Params, TypedGettersParseOrFallBack) {
  Params p{{"a", "1.5e-3"}, {"n", "-42"}, {"flag", "yes"}, {"off", "0"}, {"s", "sharp"}};
  EXPECT_DOUBLE_EQ(p.get_double("a", 0.0), 1.5e-3);
  EXPECT_DOUBLE_EQ(p.get_double("missing", 7.0), 7.0);
  EXPECT_EQ(p.get_int("n", 0), -42);
  EXPECT_EQ(p.get_int("missing", 3), 3);
  EXPECT_TRUE(p.get_bool("flag", false));
  EXPECT_FALSE(p.get_bool("off", true));
  EXPECT_EQ(p.get_string("s", ""), "sharp");
  EXPECT_EQ(p.get_string("missing", "blunt"), "blunt");
  p.set("a", "2");
  EXPECT_DOUBLE_EQ(p.get_double("a", 0.0), 2.0);
  EXPECT_TRUE(p.has("n"));
  EXPECT_FALSE(p.has("missing"));
}

TEST(Params, MalformedValuesNameTheKeyAndWhatWasExpected) {
  Params p{{"chord", "1.5x"}, {"span", ""}, {"big", "1e999"}, {"nan", "nan"}, {"count", "3.5"},
           {"huge", "99999999999"}, {"bool", "maybe"}};
  expect_cad_error([&] { p.get_double("chord", 1.0); }, CadError::Kind::BadParameter, "parameter 'chord' = '1.5x': expected a finite number");
  expect_cad_error([&] { p.get_double("span", 1.0); }, CadError::Kind::BadParameter, "'span'");
  expect_cad_error([&] { p.get_double("big", 1.0); }, CadError::Kind::BadParameter, "'big'");
  expect_cad_error([&] { p.get_double("nan", 1.0); }, CadError::Kind::BadParameter, "'nan'");
  expect_cad_error([&] { p.get_int("count", 1); }, CadError::Kind::BadParameter, "parameter 'count' = '3.5': expected an integer");
  expect_cad_error([&] { p.get_int("huge", 1); }, CadError::Kind::BadParameter, "'huge'");
  expect_cad_error([&] { p.get_bool("bool", true); }, CadError::Kind::BadParameter, "expected true or false");
}

TEST(Params, RequireKnownCatchesTypos) {
  Params p{{"naca.code", "0012"}, {"naca.spam", "2"}};
  expect_cad_error([&] { p.require_known({"naca.code", "naca.span"}, "naca"); }, CadError::Kind::BadParameter,
                   "unknown parameter 'naca.spam' for backend 'naca' (known: naca.code, naca.span)");
  Params ok{{"naca.code", "0012"}};
  EXPECT_NO_THROW(ok.require_known({"naca.code", "naca.span"}, "naca"));
}

namespace {
Registry test_registry() {
  Registry r;
  r.add(BackendInfo{"files", "reads files", {".step", ".stp"},
                    [](const Source& s) {
                      auto m = std::make_unique<Model>("files:" + s.path);
                      m->finalize();
                      return m;
                    },
                    {}});
  r.add_unavailable("vendor", "proprietary kernel", "vendor SDK not found");
  return r;
}
}  // namespace

TEST(Registry, LoadsByNameAndByExtension) {
  Registry r = test_registry();
  EXPECT_TRUE(r.has("files"));
  EXPECT_TRUE(r.available("files"));
  EXPECT_TRUE(r.has("vendor"));
  EXPECT_FALSE(r.available("vendor"));
  EXPECT_FALSE(r.available("nothing"));
  EXPECT_EQ(r.names(), (std::vector<std::string>{"files", "vendor"}));
  EXPECT_EQ(r.backend_for_path("dir.v2/Wing.STEP"), "files");
  EXPECT_EQ(r.load("files", Source{"w.stp", {}})->backend(), "files:w.stp");
}

TEST(Registry, UnknownBackendListsTheKnownOnes) {
  Registry r = test_registry();
  expect_cad_error([&] { r.load("parasolid", Source{}); }, CadError::Kind::UnknownBackend,
                   "unknown CAD backend 'parasolid' (known: files, vendor)");
}

TEST(Registry, UnavailableBackendGivesTheReason) {
  Registry r = test_registry();
  try {
    r.load("vendor", Source{});
    FAIL() << "expected CadError";
  } catch (const CadError& e) {
    EXPECT_EQ(e.kind(), CadError::Kind::BackendUnavailable);
    EXPECT_STREQ(e.what(), "backend 'vendor' is not available in this build (vendor SDK not found)");
  }
}

TEST(Registry, NoBackendForExtensionSaysHowToChooseOne) {
  Registry r = test_registry();
  expect_cad_error([&] { r.backend_for_path("wing.iges"); }, CadError::Kind::UnknownBackend,
                   "no CAD backend reads 'wing.iges' (extension '.iges'); name one with --backend");
  expect_cad_error([&] { r.backend_for_path("README"); }, CadError::Kind::UnknownBackend, "extension ''");
  // A dot in a folder name is not an extension.
  expect_cad_error([&] { r.backend_for_path("cad.stp/README"); }, CadError::Kind::UnknownBackend, "extension ''");
}

TEST(Registry, AddReplacesByName) {
  Registry r = test_registry();
  r.add_unavailable("files", "reads files", "disabled");
  EXPECT_FALSE(r.available("files"));
  EXPECT_EQ(r.names().size(), 2u);
  expect_cad_error([&] { r.load("files", Source{}); }, CadError::Kind::BackendUnavailable, "(disabled)");
}
