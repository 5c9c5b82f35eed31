// naca.* keys -> NacaWingParams.
#include "naca_validation.hpp"

#include "semimesh/cad/error.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace semimesh::mock_cad {
namespace {

[[noreturn]] void reject(const std::string& key, const std::string& value, const std::string& expected) {
  throw cad::CadError(cad::CadError::Kind::BadParameter, key + " = '" + value + "': expected " + expected);
}

std::array<double, 6> parse_box(const std::string& text) {
  const std::string expected = "6 comma-separated numbers xmin,ymin,zmin,xmax,ymax,zmax (e.g. -10,-10,0,11,10,10)";
  std::array<double, 6> box{};
  const char* cursor = text.c_str();
  for (int i = 0; i < 6; ++i) {
    char* end = nullptr;
    errno = 0;
    box[i] = std::strtod(cursor, &end);
    if (end == cursor || errno == ERANGE || !std::isfinite(box[i])) reject("naca.box", text, expected);
    while (*end == ' ') ++end;
    if (i < 5 && *end != ',') reject("naca.box", text, expected);
    cursor = i < 5 ? end + 1 : end;
  }
  if (*cursor != '\0') reject("naca.box", text, expected);
  return box;
}

}  // namespace

std::array<double, 6> fuselage_default_box(double wall_radius, double wall_angle_deg) {
  const double x0 = -10.0, x1 = 11.0, slope = std::tan(wall_angle_deg * M_PI / 180.0);
  const double r = wall_radius, r_max = std::max(r + slope * x0, r + slope * x1);
  return {x0, -r_max - 10.0, -r - r_max - 10.0, x1, r_max + 10.0, 10.0};
}

NacaWingParams naca_params_from(const cad::Params& p) {
  p.require_known({"naca.code", "naca.chord", "naca.span", "naca.taper", "naca.sweep", "naca.te", "naca.farfield",
                   "naca.box", "naca.units", "naca.shape", "naca.tip", "naca.wall", "naca.wall_radius", "naca.wall_angle", "naca.dihedral"},
                  "naca");
  NacaWingParams out;
  out.code = p.get_string("naca.code", out.code);
  out.chord = p.get_double("naca.chord", out.chord);
  out.span = p.get_double("naca.span", out.span);
  out.taper = p.get_double("naca.taper", out.taper);
  out.sweep_deg = p.get_double("naca.sweep", out.sweep_deg);
  out.dihedral_deg = p.get_double("naca.dihedral", out.dihedral_deg);
  const std::string te = p.get_string("naca.te", "blunt");
  if (te != "blunt" && te != "sharp") reject("naca.te", te, "blunt (squared-off trailing edge) or sharp");
  out.sharp_te = te == "sharp";
  out.farfield = p.get_bool("naca.farfield", out.farfield);
  const std::string wall = p.get_string("naca.wall", "plane");
  if (wall != "plane" && wall != "cylinder" && wall != "cone")
    reject("naca.wall", wall,
           "plane (the wall z = 0), cylinder (a circular fuselage along x, crest at z = 0) or cone (a conical one)");
  out.fuselage = wall != "plane";
  out.wall_radius = p.get_double("naca.wall_radius", 1.5 * out.chord);
  if (!out.fuselage && p.has("naca.wall_radius"))
    reject("naca.wall_radius", p.get_string("naca.wall_radius", ""), "unset unless naca.wall = cylinder or cone (the plane has no radius)");
  out.wall_angle_deg = p.get_double("naca.wall_angle", wall == "cone" ? 5.0 : 0.0);
  if (wall != "cone" && p.has("naca.wall_angle"))
    reject("naca.wall_angle", p.get_string("naca.wall_angle", ""), "unset unless naca.wall = cone");
  if (wall == "cone" && out.wall_angle_deg == 0.0)
    reject("naca.wall_angle", "0", "a half angle other than 0 for naca.wall = cone (0 is naca.wall = cylinder)");
  if (out.fuselage) out.box = fuselage_default_box(out.wall_radius, out.wall_angle_deg);
  if (p.has("naca.box")) out.box = parse_box(p.get_string("naca.box", ""));
  out.units = p.get_string("naca.units", out.units);
  const std::string shape = p.get_string("naca.shape", "wing");
  if (shape != "wing" && shape != "revolution")
    reject("naca.shape", shape, "wing (a wing on a wall) or revolution (the section's thickness revolved about the chord line)");
  out.revolution = shape == "revolution";
  const std::string tip = p.get_string("naca.tip", "flat");
  if (tip != "flat" && tip != "round")
    reject("naca.tip", tip, "flat (a plane cap) or round (the tip section revolved about its camber line)");
  out.round_tip = tip == "round";
  detail::validate(out);
  return out;
}

}  // namespace semimesh::mock_cad
