// FreeCAD documents (.FCStd): a zip archive holding Document.xml and one BREP file per shape.
//
// Which shape is taken: Document.xml's <ObjectData> lists every object with its properties; an
// object bears a shape when it has a property of type "Part::PropertyPartShape" whose <Part file=...>
// names a .brp/.brep member of the archive. Of those, the LAST in document order (FreeCAD writes
// objects in creation order, so this is the final feature of a modelling history) that is visible
// (a "Visibility" property that is true, or none at all: older files keep visibility in
// GuiDocument.xml) and whose shape holds a solid; failing that, the last visible one holding
// faces; failing that, the last one holding faces. FreeCAD models in millimetres.
#include "read_shape.hpp"
#include "semimesh/cad/error.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <pugixml.hpp>
#include <zip.h>

#include <memory>
#include <optional>
#include <sstream>

namespace semimesh::occ {
namespace {

using cad::CadError;

struct ZipCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
using Archive = std::unique_ptr<zip_t, ZipCloser>;

/// The bytes of one member, or nullopt when the archive has no such member.
std::optional<std::string> read_member(zip_t* archive, const std::string& name, const std::string& path) {
  zip_stat_t stat;
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) return std::nullopt;
  std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> file(zip_fopen(archive, name.c_str(), 0), zip_fclose);
  if (!file) throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': cannot read member '" + name + "'");
  std::string bytes(static_cast<size_t>(stat.size), '\0');
  if (zip_fread(file.get(), bytes.data(), stat.size) != static_cast<zip_int64_t>(stat.size))
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': member '" + name + "' is truncated");
  return bytes;
}

struct Candidate {
  std::string object;
  TopoDS_Shape shape;
  bool visible = true;
  bool has_solid = false;
};

}  // namespace

ReadShape read_fcstd(const std::string& path) {
  int error = 0;
  Archive archive(zip_open(path.c_str(), ZIP_RDONLY, &error));
  if (!archive) throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': not a FreeCAD document (not a zip archive)");
  const std::optional<std::string> xml = read_member(archive.get(), "Document.xml", path);
  if (!xml) throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': not a FreeCAD document (no Document.xml)");
  pugi::xml_document document;
  if (!document.load_buffer(xml->data(), xml->size()))
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': Document.xml is not valid XML");

  std::vector<Candidate> candidates;
  for (pugi::xml_node object : document.child("Document").child("ObjectData").children("Object")) {
    Candidate candidate{object.attribute("name").as_string(), {}, true, false};
    std::string brep_name;
    for (pugi::xml_node property : object.child("Properties").children("Property")) {
      const std::string type = property.attribute("type").as_string();
      if (type == "Part::PropertyPartShape") brep_name = property.child("Part").attribute("file").as_string();
      if (std::string(property.attribute("name").as_string()) == "Visibility")
        candidate.visible = property.child("Bool").attribute("value").as_string("true") == std::string("true");
    }
    if (brep_name.empty()) continue;
    const std::optional<std::string> brep = read_member(archive.get(), brep_name, path);
    if (!brep) continue;
    std::istringstream stream(*brep);
    BRep_Builder builder;
    BRepTools::Read(candidate.shape, stream, builder);
    if (candidate.shape.IsNull() || !TopExp_Explorer(candidate.shape, TopAbs_FACE).More()) continue;
    candidate.has_solid = TopExp_Explorer(candidate.shape, TopAbs_SOLID).More();
    candidates.push_back(std::move(candidate));
  }
  if (candidates.empty())
    throw CadError(CadError::Kind::NoGeometry, "'" + path + "': the FreeCAD document has no object with faces");

  auto last_where = [&](auto predicate) -> const Candidate* {
    for (auto it = candidates.rbegin(); it != candidates.rend(); ++it)
      if (predicate(*it)) return &*it;
    return nullptr;
  };
  const Candidate* chosen = last_where([](const Candidate& c) { return c.visible && c.has_solid; });
  if (!chosen) chosen = last_where([](const Candidate& c) { return c.visible; });
  if (!chosen) chosen = &candidates.back();

  ReadShape out;
  out.shape = chosen->shape;
  out.unit = "mm";
  return out;
}

}  // namespace semimesh::occ
