#include "read_shape.hpp"

#include "quiet_messages.hpp"
#include "semimesh/cad/error.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace semimesh::occ {
namespace {

using cad::CadError;

struct UnitInfo {
  const char* label;
  double mm;  ///< millimetres per unit
};

/// Length unit from the names STEP (SI prefix + "METRE" or conversion-based names) and IGES
/// (global section unit name) use; nullptr when not recognised.
const UnitInfo* unit_from_name(std::string name) {
  static const std::pair<const char*, UnitInfo> kUnits[] = {
      {"MILLIMETRE", {"mm", 1.0}}, {"MILLIMETER", {"mm", 1.0}}, {"MM", {"mm", 1.0}},
      {"CENTIMETRE", {"cm", 10.0}}, {"CENTIMETER", {"cm", 10.0}}, {"CM", {"cm", 10.0}},
      {"METRE", {"m", 1000.0}}, {"METER", {"m", 1000.0}}, {"M", {"m", 1000.0}},
      {"KILOMETRE", {"km", 1e6}}, {"KM", {"km", 1e6}},
      {"MICROMETRE", {"um", 1e-3}}, {"UM", {"um", 1e-3}}, {"MICRON", {"um", 1e-3}},
      {"INCH", {"in", 25.4}}, {"IN", {"in", 25.4}}, {"FOOT", {"ft", 304.8}}, {"FT", {"ft", 304.8}},
  };
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  for (const auto& [key, info] : kUnits)
    if (name == key) return &info;
  return nullptr;
}

// The entries of unit_from_name's table, once per label.
std::vector<std::string> unit_labels() {
  std::vector<std::string> labels;
  for (const char* name : {"MM", "CM", "M", "KM", "UM", "IN", "FT"}) labels.push_back(unit_from_name(name)->label);
  return labels;
}

void require_readable(const std::string& path) {
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw CadError(CadError::Kind::FileNotFound, "cannot open '" + path + "': no such file");
}

void require_faces(const TopoDS_Shape& shape, const std::string& path, const char* format) {
  if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_FACE).More())
    throw CadError(CadError::Kind::NoGeometry,
                   std::string("'") + path + "': the " + format + " file holds no faces or solids");
}

ReadShape read_step(const std::string& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': not a readable STEP file");
  reader.TransferRoots();
  ReadShape out;
  out.shape = reader.OneShape();
  require_faces(out.shape, path, "STEP");

  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (!lengths.IsEmpty())
    if (const UnitInfo* unit = unit_from_name(lengths.First().ToCString())) {
      out.unit = unit->label;
      out.to_file_unit = 1.0 / unit->mm;
      out.declared = std::string("STEP length unit '") + lengths.First().ToCString() + "'";
    }

  // Face names: the name of the STEP entity each face was made from (ADVANCED_FACE('name', ...)).
  const Handle(XSControl_TransferReader)& transfer = reader.WS()->TransferReader();
  for (TopExp_Explorer f(out.shape, TopAbs_FACE); f.More(); f.Next()) {
    Handle(StepRepr_RepresentationItem) item =
        Handle(StepRepr_RepresentationItem)::DownCast(transfer->EntityFromShapeResult(f.Current(), 1));
    if (!item.IsNull() && !item->Name().IsNull()) out.face_names.emplace_back(f.Current(), item->Name()->ToCString());
  }
  return out;
}

ReadShape read_iges(const std::string& path) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': not a readable IGES file");
  reader.TransferRoots();
  ReadShape out;
  out.shape = reader.OneShape();
  require_faces(out.shape, path, "IGES");
  Handle(TCollection_HAsciiString) unit_name = reader.IGESModel()->GlobalSection().UnitName();
  if (!unit_name.IsNull())
    if (const UnitInfo* unit = unit_from_name(unit_name->ToCString())) {
      out.unit = unit->label;
      out.to_file_unit = 1.0 / unit->mm;
      out.declared = std::string("IGES global section unit '") + unit_name->ToCString() + "'";
    }
  return out;
}

/// Whether the file starts like an OCC text BREP: BRepTools::Write puts "CASCADE Topology V<n>"
/// on its first or second line (after "DBRep_DrawableShape"); BRepTools::Read would otherwise
/// print its complaint and return an empty shape.
bool has_brep_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(256, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find("CASCADE Topology V") != std::string::npos;
}

ReadShape read_brep(const std::string& path) {
  if (!has_brep_header(path))
    throw CadError(CadError::Kind::FileUnreadable,
                   "'" + path + "': not a BREP file (no 'CASCADE Topology V...' header in its first lines)");
  ReadShape out;
  BRep_Builder builder;
  if (!BRepTools::Read(out.shape, path.c_str(), builder))
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': not a readable BREP file");
  require_faces(out.shape, path, "BREP");
  return out;
}

}  // namespace

const std::vector<std::string>& known_unit_labels() {
  static const std::vector<std::string> labels = unit_labels();
  return labels;
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

ReadShape read_shape(const std::string& path) {
  const std::string ext = extension_of(path);
  using Reader = ReadShape (*)(const std::string&);
  Reader reader = nullptr;
  if (ext == ".step" || ext == ".stp") reader = read_step;
  else if (ext == ".iges" || ext == ".igs") reader = read_iges;
  else if (ext == ".brep" || ext == ".brp") reader = read_brep;
  else if (ext == ".fcstd") reader = read_fcstd;
  else
    throw CadError(CadError::Kind::BadParameter, "'" + path + "': unknown CAD file extension '" + ext +
                                                     "' (the occ backend reads .step .stp .iges .igs .brep .brp .fcstd)");
  require_readable(path);
  const QuietMessages quiet;
  try {
    return reader(path);
  } catch (const Standard_Failure& failure) {
    throw CadError(CadError::Kind::FileUnreadable, "'" + path + "': OpenCASCADE failed to read it: " +
                                                       failure.GetMessageString());
  }
}

}  // namespace semimesh::occ
