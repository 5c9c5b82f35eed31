// The registry factory: read (or generate), scale once, sew, heal, map onto a cadapi Model.
#include "naca_edge_names.hpp"
#include "prepare_shape.hpp"
#include "read_shape.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace semimesh::occ {
namespace {

using cad::CadError;

const char* const kBackend = "occ";

FluidSide fluid_side_from(const cad::Params& params) {
  const std::string value = params.get_string("occ.fluid_inside", "auto");
  if (value == "auto") return FluidSide::Auto;
  return params.get_bool("occ.fluid_inside", false) ? FluidSide::Inside : FluidSide::Outside;
}

double diagonal_of(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

std::string number_label(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The unit of the model's numbers (after occ.scale): occ.units when set (a known label: files often
// declare a wrong one), else what the file declares.
std::string file_unit(const cad::Params& params, const ReadShape& read) {
  if (!params.has("occ.units")) return read.unit;
  const std::string unit = params.get_string("occ.units", "");
  const auto& known = known_unit_labels();
  if (std::find(known.begin(), known.end(), unit) == known.end()) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'occ.units' = '" + unit + "': unknown length unit (known: " + list + ")");
  }
  return unit;
}

std::string unit_origin(const cad::Params& params, const ReadShape& read) {
  const std::string declared = read.declared.empty() ? "the file declares no unit" : "the file declares " + read.unit +
                                                                                        " (" + read.declared + ")";
  if (params.has("occ.units")) return "set by occ.units (geometry.units); " + declared;
  return read.declared.empty() ? "the file declares no unit: its numbers as they are" : "declared by the file (" + read.declared + ")";
}

std::unique_ptr<cad::Model> load_file(const cad::Source& source) {
  const cad::Params& params = source.params;
  params.require_known({"occ.scale", "occ.units", "occ.sew", "occ.sew_tolerance", "occ.heal", "occ.fluid_inside"},
                       kBackend);
  const double scale = params.get_double("occ.scale", 1.0);
  if (!(scale > 0.0))
    throw CadError(CadError::Kind::BadParameter, "parameter 'occ.scale' = " + number_label(scale) + ": expected a positive number");
  const FluidSide fluid_side = fluid_side_from(params);

  ReadShape read = read_shape(source.path);
  TopoDS_Shape shape = scale_shape(read.shape, read.to_file_unit * scale, read.face_names);

  const double tolerance = params.get_double("occ.sew_tolerance", 1e-6 * diagonal_of(shape));
  if (!(tolerance > 0.0))
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'occ.sew_tolerance' = " + number_label(tolerance) + ": expected a positive length");
  if (params.get_bool("occ.sew", true)) shape = sew_shape(shape, tolerance, read.face_names);
  if (params.get_bool("occ.heal", true)) shape = heal_shape(shape, tolerance, read.face_names);

  ModelOptions options;
  options.scale_applied = scale;
  const std::string unit = file_unit(params, read);
  options.units = scale == 1.0 || params.has("occ.units") ? unit : unit + " x " + number_label(scale);
  options.units_origin = unit_origin(params, read);
  options.fluid_side = fluid_side;
  options.face_names = std::move(read.face_names);
  try {
    return model_from_shape(shape, kBackend, options);
  } catch (const CadError& error) {
    throw CadError(error.kind(), "'" + source.path + "': " + error.what());
  }
}

std::unique_ptr<cad::Model> generate_wing(const cad::Source& source) {
  cad::Params naca_params;
  ModelOptions options;
  for (const auto& [key, value] : source.params.all()) {
    if (key.rfind("naca.", 0) == 0) naca_params.set(key, value);
    else if (key != "occ.scale" && key != "occ.units")
      throw CadError(CadError::Kind::BadParameter, "parameter '" + key +
                                                       "' does not apply to the generated NACA wing of backend 'occ' "
                                                       "(use naca.* keys, occ.scale and occ.units)");
  }
  const mock_cad::NacaWingParams wing = mock_cad::naca_params_from(naca_params);
  const double scale = source.params.get_double("occ.scale", 1.0);
  if (!(scale > 0.0))
    throw CadError(CadError::Kind::BadParameter, "parameter 'occ.scale' = " + number_label(scale) + ": expected a positive number");

  TopoDS_Shape shape = make_naca_wing_shape(wing);
  const std::vector<std::string> names = naca_wing_face_names(wing);
  int index = 0;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) options.face_names.emplace_back(f.Current(), names.at(index++));
  shape = scale_shape(shape, scale, options.face_names);
  options.edge_names = naca_wing_edge_names(shape, options.face_names);  // the analytic curve names
  options.scale_applied = scale;
  options.units = source.params.get_string("occ.units", scale == 1.0 ? "chord" : "chord x " + number_label(scale));
  options.units_origin = source.params.has("occ.units") ? "set by occ.units (geometry.units)" : "the generated wing, in chords";
  return model_from_shape(shape, kBackend, options);
}

}  // namespace

std::unique_ptr<cad::Model> load_occ(const cad::Source& source) {
  return source.path.empty() ? generate_wing(source) : load_file(source);
}

}  // namespace semimesh::occ
