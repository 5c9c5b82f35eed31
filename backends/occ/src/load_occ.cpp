// The registry factory: read (or generate), scale once, sew, heal, map onto a cadapi Model.
#include "fluid_domain.hpp"
#include "naca_edge_names.hpp"
#include "prepare_shape.hpp"
#include "read_shape.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
#include <cmath>
#include <sstream>

namespace semimesh::occ {
namespace {

using cad::CadError;

const char* const kBackend = "occ";

// The sewing tolerance's range, as fractions of the model's bounding-box diagonal: the first is
// round-off of a sewn export; the last stays far below any feature a wing mesh resolves (a blunt
// trailing edge is ~1e-3 of the model).
constexpr double kFirstSewFraction = 1e-6;
constexpr double kLastSewFraction = 1e-4;

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

// A comma-separated list of `count` finite numbers, or a rejection naming the key.
template <std::size_t N>
std::array<double, N> numbers(const cad::Params& params, const std::string& key, const char* expected) {
  const std::string text = params.get_string(key, "");
  std::array<double, N> out{};
  std::istringstream in(text);
  for (std::size_t i = 0; i < N; ++i) {
    std::string item;
    std::getline(in, item, ',');
    char* end = nullptr;
    out[i] = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(out[i]))
      throw CadError(CadError::Kind::BadParameter, "parameter '" + key + "' = '" + text + "': expected " + expected);
  }
  if (std::string rest; std::getline(in, rest))
    throw CadError(CadError::Kind::BadParameter, "parameter '" + key + "' = '" + text + "': expected " + expected);
  return out;
}

std::string list_text(const double* x, std::size_t n) {
  std::string text = "[";
  for (std::size_t i = 0; i < n; ++i) text += (i ? ", " : "") + number_label(x[i]);
  return text + "]";
}

// One occ.farfield_*: the far field built around a body-only file or joined parts.
std::optional<FarFieldShape> far_field_request(const cad::Params& params) {
  FarFieldShape shape;
  if (params.has("occ.farfield_box")) {
    shape.box = numbers<6>(params, "occ.farfield_box", "6 numbers: xmin, ymin, zmin, xmax, ymax, zmax");
    const auto& b = *shape.box;
    if (!(b[0] < b[3] && b[1] < b[4] && b[2] < b[5]))
      throw CadError(CadError::Kind::BadParameter, "parameter 'occ.farfield_box': expected each min < max");
    shape.label = "geometry.farfield = {box = " + list_text(b.data(), 6) + "}";
  } else if (params.has("occ.farfield_sphere")) {
    shape.sphere = numbers<4>(params, "occ.farfield_sphere", "4 numbers: centre x, y, z, radius");
    const auto& s = *shape.sphere;
    if (!(s[3] > 0.0)) throw CadError(CadError::Kind::BadParameter, "parameter 'occ.farfield_sphere': expected a radius > 0");
    shape.label = "geometry.farfield = {sphere = {centre = " + list_text(s.data(), 3) + ", radius = " + number_label(s[3]) + "}}";
  } else if (params.has("occ.farfield_box_chords")) {
    shape.box_chords = params.get_double("occ.farfield_box_chords", 0.0);
    if (!(*shape.box_chords > 0.0))
      throw CadError(CadError::Kind::BadParameter, "parameter 'occ.farfield_box_chords': expected a number > 0");
    shape.label = "geometry.farfield = {box_chords = " + number_label(*shape.box_chords) + "}";
  } else {
    return std::nullopt;
  }
  return shape;
}

// A parameter holding a list: one entry per line (as the pipeline writes it, names may hold
// commas), or comma-separated when on one line (as typed: cad-info --param occ.join_body=#1,#2).
std::vector<std::string> entries_of(const std::string& text) {
  const char separator = text.find('\n') != std::string::npos ? '\n' : ',';
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string entry; std::getline(in, entry, separator);)
    if (!entry.empty()) out.push_back(entry);
  return out;
}

// What to build around the file's shape: nothing, a wall plane and a far field (a body-only file),
// or the join of two of its parts inside a far field (an assembly).
struct DomainRequest {
  std::optional<WallPlane> wall_plane;
  std::optional<PartsToJoin> join;
  FarFieldShape far;
  std::optional<CutPlane> body_cut;
};

// occ.body_cut: the plane the body is cut at (geometry.body_cut), its normal towards the part to take away.
std::optional<CutPlane> body_cut_request(const cad::Params& params) {
  if (!params.has("occ.body_cut")) return std::nullopt;
  const auto c = numbers<6>(params, "occ.body_cut", "6 numbers: point x, y, z, normal x, y, z");
  const gp_Vec normal(c[3], c[4], c[5]);
  if (normal.Magnitude() == 0.0) throw CadError(CadError::Kind::BadParameter, "parameter 'occ.body_cut': the normal is zero");
  return CutPlane{gp_Pnt(c[0], c[1], c[2]), gp_Dir(normal),
                  "geometry.body_cut = {point = " + list_text(c.data(), 3) + ", normal = " + list_text(c.data() + 3, 3) + "}"};
}

std::optional<DomainRequest> domain_request(const cad::Params& params) {
  const std::optional<FarFieldShape> far = far_field_request(params);
  const bool join = params.has("occ.join_body") || params.has("occ.join_wall");
  const bool plane = params.has("occ.wall_plane");
  if (!plane && !join && !far) {
    if (params.has("occ.body_cut"))
      throw CadError(CadError::Kind::BadParameter,
                     "parameter 'occ.body_cut' (geometry.body_cut) cuts a body the far field is built around: it goes "
                     "with 'occ.wall_plane' (geometry.wall_plane) or 'occ.join_*' (geometry.join)");
    return std::nullopt;
  }
  if (plane && join)
    throw CadError(CadError::Kind::BadParameter,
                   "parameters 'occ.wall_plane' (geometry.wall_plane) and 'occ.join_*' (geometry.join) exclude each "
                   "other: a body-only file stands on a plane, an assembly's body on the wall part it is joined to");
  if ((!plane && !join) || !far)
    throw CadError(CadError::Kind::BadParameter,
                   "parameters 'occ.wall_plane' (geometry.wall_plane) or 'occ.join_body' and 'occ.join_wall' "
                   "(geometry.join), and one of 'occ.farfield_box', 'occ.farfield_sphere', 'occ.farfield_box_chords' "
                   "(geometry.farfield = {box | sphere | box_chords}) go together: the far field is built around a "
                   "body-only file or the joined parts of an assembly");
  DomainRequest request{std::nullopt, std::nullopt, *far, body_cut_request(params)};
  if (join) {
    request.join = PartsToJoin{entries_of(params.get_string("occ.join_body", "")), entries_of(params.get_string("occ.join_wall", ""))};
    return request;
  }
  const auto w = numbers<6>(params, "occ.wall_plane", "6 numbers: point x, y, z, normal x, y, z");
  const gp_Vec normal(w[3], w[4], w[5]);
  if (normal.Magnitude() == 0.0)
    throw CadError(CadError::Kind::BadParameter, "parameter 'occ.wall_plane': the normal is zero");
  request.wall_plane = WallPlane{gp_Pnt(w[0], w[1], w[2]), gp_Dir(normal),
                                 "geometry.wall_plane = {point = " + list_text(w.data(), 3) + ", normal = " +
                                     list_text(w.data() + 3, 3) + "}"};
  return request;
}

std::unique_ptr<cad::Model> load_file(const cad::Source& source) {
  const cad::Params& params = source.params;
  params.require_known({"occ.scale", "occ.units", "occ.sew", "occ.sew_tolerance", "occ.heal", "occ.fluid_inside",
                        "occ.wall_plane", "occ.farfield_box", "occ.farfield_sphere", "occ.farfield_box_chords",
                        "occ.join_body", "occ.join_wall", "occ.body_cut"},
                       kBackend);
  const auto domain = domain_request(params);
  const double scale = params.get_double("occ.scale", 1.0);
  if (!(scale > 0.0))
    throw CadError(CadError::Kind::BadParameter, "parameter 'occ.scale' = " + number_label(scale) + ": expected a positive number");
  const FluidSide fluid_side = fluid_side_from(params);

  ReadShape read = read_shape(source.path);
  TopoDS_Shape shape = scale_shape(read.shape, read.to_file_unit * scale, read.face_names);

  // Sewing: from a millionth of the model's size, up to a ten-thousandth while that closes more
  // gaps (sew_shape); a tolerance the user sets is used as it is.
  const double diagonal = diagonal_of(shape);
  double tolerance = params.get_double("occ.sew_tolerance", kFirstSewFraction * diagonal);
  if (!(tolerance > 0.0))
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'occ.sew_tolerance' = " + number_label(tolerance) + ": expected a positive length");
  std::vector<std::string> repairs;
  if (params.get_bool("occ.sew", true)) {
    const double most = params.has("occ.sew_tolerance") ? tolerance : kLastSewFraction * diagonal;
    Sewn sewn = sew_shape(shape, tolerance, most, read.face_names);
    shape = std::move(sewn.shape);
    tolerance = sewn.tolerance;
    if (sewn.joined > 0)
      repairs.push_back("sewn " + std::to_string(sewn.joined) + " pair(s) of edges within " + number_label(tolerance) +
                        " (" + number_label(tolerance / diagonal) + " of the model's size), " +
                        std::to_string(sewn.free) + " edge(s) left free" +
                        (params.has("occ.sew_tolerance") ? " (geometry.sew_tolerance)" : ""));
  }
  if (params.get_bool("occ.heal", true)) shape = heal_shape(shape, tolerance, read.face_names);
  if (domain) {
    try {
      shape = domain->join ? fluid_domain_of_parts(shape, *domain->join, domain->far, domain->body_cut, 10.0 * tolerance,
                                                   read.face_names, repairs)
                           : fluid_domain(shape, *domain->wall_plane, domain->far, domain->body_cut, 10.0 * tolerance,
                                          read.face_names, repairs);
    } catch (const CadError& error) {
      throw CadError(error.kind(), "'" + source.path + "': " + error.what());
    }
  }

  ModelOptions options;
  options.scale_applied = scale;
  const std::string unit = file_unit(params, read);
  options.units = scale == 1.0 || params.has("occ.units") ? unit : unit + " x " + number_label(scale);
  options.units_origin = unit_origin(params, read);
  options.fluid_side = domain ? FluidSide::Inside : fluid_side;
  options.face_names = std::move(read.face_names);
  options.repairs = std::move(repairs);
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
  if (wing.round_tip)
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'naca.tip' = 'round': the generated B-spline wing of backend 'occ' has a flat tip "
                   "(the rounded tip is backend 'naca''s)");
  if (wing.dihedral_deg != 0.0)
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'naca.dihedral': the generated B-spline wing of backend 'occ' has no dihedral "
                   "(the dihedral is backend 'naca''s)");
  if (wing.fuselage)
    throw CadError(CadError::Kind::BadParameter,
                   "parameter 'naca.wall': the generated B-spline wing of backend 'occ' stands on the plane z = 0 (the "
                   "cylinder and cone walls are backend 'naca''s)");
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
  try {
    return source.path.empty() ? generate_wing(source) : load_file(source);
  } catch (const Standard_Failure& failure) {
    // An OCC exception is no std::exception: uncaught, the command line could only say "unknown".
    const std::string what = source.path.empty() ? std::string("the generated wing") : "'" + source.path + "'";
    throw CadError(CadError::Kind::FileUnreadable, what + ": OpenCASCADE failed while building the model (" +
                                                       failure.DynamicType()->Name() + ": " +
                                                       failure.GetMessageString() + ")");
  }
}

}  // namespace semimesh::occ
