// FreeCAD documents: a fixture .FCStd (zip with Document.xml and BREP members) written here with
// libzip, since no FreeCAD file is available.
#include "occ_test_support.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <gtest/gtest.h>
#include <unistd.h>
#include <zip.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include "temp_path.hpp"

namespace semimesh::occ::test {
namespace {

std::string brep_text(const TopoDS_Shape& shape) {
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

struct Member {
  std::string name, bytes;
};

/// Writes a zip archive holding the members (libzip copies the buffers on close).
void write_zip(const std::string& path, const std::vector<Member>& members) {
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(archive, nullptr);
  for (const Member& m : members) {
    zip_source_t* source = zip_source_buffer(archive, m.bytes.data(), m.bytes.size(), 0);
    ASSERT_GE(zip_file_add(archive, m.name.c_str(), source, ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(archive), 0);
}

/// A Document.xml in FreeCAD's layout: each object's Shape property names its BREP member.
std::string document_xml(const std::vector<std::tuple<std::string, std::string, bool>>& objects) {
  std::ostringstream xml;
  xml << "<?xml version='1.0' encoding='utf-8'?>\n<Document SchemaVersion=\"4\" FileVersion=\"1\">\n"
      << "<Objects Count=\"" << objects.size() << "\">\n";
  for (const auto& [name, file, visible] : objects) xml << "<Object type=\"Part::Feature\" name=\"" << name << "\"/>\n";
  xml << "</Objects>\n<ObjectData Count=\"" << objects.size() << "\">\n";
  for (const auto& [name, file, visible] : objects) {
    xml << "<Object name=\"" << name << "\"><Properties Count=\"3\">\n"
        << "<Property name=\"Label\" type=\"App::PropertyString\"><String value=\"" << name << "\"/></Property>\n"
        << "<Property name=\"Shape\" type=\"Part::PropertyPartShape\"><Part file=\"" << file << "\"/></Property>\n"
        << "<Property name=\"Visibility\" type=\"App::PropertyBool\"><Bool value=\"" << (visible ? "true" : "false")
        << "\"/></Property>\n</Properties></Object>\n";
  }
  xml << "</ObjectData>\n</Document>\n";
  return xml.str();
}

std::string temp_path(const std::string& name) {
  return semimesh::test::temp_path("occ_" + name).string();
}

// A visible box created first, a hidden sphere after it: the rule picks the last VISIBLE solid.
TEST(OccFcstd, LoadsTheLastVisibleSolid) {
  const std::string path = temp_path("fixture.FCStd");
  write_zip(path, {{"Document.xml", document_xml({{"Box", "PartShape.brp", true}, {"Sphere", "PartShape1.brp", false}})},
                   {"PartShape.brp", brep_text(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape())},
                   {"PartShape1.brp", brep_text(BRepPrimAPI_MakeSphere(5.0).Shape())}});
  auto model = load_occ(cad::Source{path, {}});
  std::remove(path.c_str());
  EXPECT_EQ(model->num_surfaces(), 6);
  EXPECT_EQ(model->num_curves(), 12);
  EXPECT_TRUE(model->is_closed());
  EXPECT_EQ(model->units(), "mm");
  EXPECT_NEAR((model->bbox().hi - cad::Vec3(10, 20, 30)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(model->bbox().lo.norm(), 0.0, 1e-9);
  // Outward normals of the box: the flux of x.n is 3 x volume.
  EXPECT_NEAR(position_flux(*model), 3 * 6000.0, 1.0);
}

TEST(OccFcstd, LaterVisibleSolidWins) {
  const std::string path = temp_path("fixture2.fcstd");
  write_zip(path, {{"Document.xml", document_xml({{"Box", "PartShape.brp", true}, {"Sphere", "PartShape1.brp", true}})},
                   {"PartShape.brp", brep_text(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape())},
                   {"PartShape1.brp", brep_text(BRepPrimAPI_MakeSphere(5.0).Shape())}});
  auto model = load_occ(cad::Source{path, {}});
  std::remove(path.c_str());
  EXPECT_EQ(model->num_surfaces(), 1);
  EXPECT_NEAR(model->bbox().hi.x(), 5.0, 1e-6);
  EXPECT_EQ(model->surface(0).kind(), cad::SurfaceKind::Sphere);
}

TEST(OccFcstd, ArchiveWithoutDocumentIsUnreadable) {
  const std::string path = temp_path("nodoc.FCStd");
  write_zip(path, {{"PartShape.brp", brep_text(BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape())}});
  try {
    load_occ(cad::Source{path, {}});
    ADD_FAILURE() << "no error";
  } catch (const cad::CadError& error) {
    EXPECT_EQ(error.kind(), cad::CadError::Kind::FileUnreadable);
    EXPECT_NE(std::string(error.what()).find("Document.xml"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace semimesh::occ::test
