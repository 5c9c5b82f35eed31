// Readers of CAD files into an OCC shape, with the face names and the length unit they carry.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <utility>
#include <vector>

namespace semimesh::occ {

struct ReadShape {
  TopoDS_Shape shape;
  std::vector<std::pair<TopoDS_Shape, std::string>> face_names;
  std::string unit = "file";  ///< the file's length unit ("mm", "m", "in", ...) or "file"
  /// Factor from the coordinates OCC produced to the file's unit (OCC's STEP and IGES readers
  /// convert to millimetres; this undoes it so coordinates stay in the file's unit).
  double to_file_unit = 1.0;
  /// Where the unit comes from, e.g. "STEP length unit 'MILLIMETRE'"; empty when the file says none.
  std::string declared;
};

/// The unit labels a file may declare (and occ.units may set): mm, cm, m, km, um, in, ft.
const std::vector<std::string>& known_unit_labels();

/// Dispatches on the extension (any case). Throws CadError: FileNotFound when `path` cannot be
/// opened, FileUnreadable when it does not parse, NoGeometry when it holds no faces,
/// BadParameter on an unknown extension.
ReadShape read_shape(const std::string& path);

/// The shape of a FreeCAD document (see fcstd.cpp for which object is taken).
ReadShape read_fcstd(const std::string& path);

/// Lower-case extension with its dot ("" when none).
std::string extension_of(const std::string& path);

}  // namespace semimesh::occ
