#include "naca_validation.hpp"

#include "naca_wing.hpp"
#include "round_tip.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>

namespace semimesh::mock_cad::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCapSamples = 200;  // per parameter of the rounded tip, for its extent

[[noreturn]] void reject(const std::string& key, const std::string& value, const std::string& expected) {
  throw cad::CadError(cad::CadError::Kind::BadParameter, key + " = '" + value + "': expected " + expected);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string box_text(const std::array<double, 6>& box) {
  std::string out;
  for (double v : box) out += (out.empty() ? "" : ",") + number(v);
  return out;
}

}  // namespace

NacaDigits parse_naca_code(const std::string& code) {
  const bool four_digits =
      code.size() == 4 && std::all_of(code.begin(), code.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!four_digits) reject("naca.code", code, "4 digits MPTT (e.g. 0012)");
  NacaDigits d;
  d.max_camber = (code[0] - '0') / 100.0;
  d.camber_position = (code[1] - '0') / 10.0;
  d.thickness = std::stoi(code.substr(2)) / 100.0;
  if (d.thickness == 0.0) reject("naca.code", code, "a thickness TT of at least 01 (e.g. 0012); 00 has no thickness");
  // The camber parabolas divide by p^2 and (1 - p)^2: a cambered code needs P in 1..9.
  if (d.max_camber > 0.0 && d.camber_position == 0.0)
    reject("naca.code", code, "a camber position P in 1..9 when the maximum camber M is set (e.g. 2412)");
  return d;
}

void validate(const NacaWingParams& p) {
  const NacaDigits digits = parse_naca_code(p.code);
  if (!(p.chord > 0.0)) reject("naca.chord", number(p.chord), "a root chord > 0");
  if (!(p.span > 0.0)) reject("naca.span", number(p.span), "a semi-span > 0 (the wing height above the wall z = 0)");
  if (!(p.taper > 0.0)) reject("naca.taper", number(p.taper), "a taper ratio (tip chord / root chord) > 0");
  if (!(std::abs(p.sweep_deg) < 80.0)) reject("naca.sweep", number(p.sweep_deg), "a sweep angle in degrees with |sweep| < 80");
  if (p.units.empty()) reject("naca.units", p.units, "a unit name (e.g. chord, m, mm)");
  if (p.revolution) {
    const std::string what = "for naca.shape = revolution";
    if (digits.max_camber > 0.0) reject("naca.code", p.code, "a symmetric code 00TT " + what);
    if (!p.sharp_te) reject("naca.te", "blunt", "sharp " + what + " (the tail is a pole)");
    if (p.farfield) reject("naca.farfield", "true", "false " + what + " (the body has no wall)");
    if (p.round_tip) reject("naca.tip", "round", "flat " + what + " (the body has no tip)");
    return;
  }
  if (!p.farfield) return;

  const auto& b = p.box;
  if (b[2] != 0.0) reject("naca.box", box_text(b), "zmin = 0 (the wall is the plane z = 0), got zmin = " + number(b[2]));
  // The wing is the ruled hull of its root and tip sections (linear planform).
  const NacaWing wing(NacaSection(digits, p.sharp_te), p.chord, p.span, p.taper, p.sweep_deg);
  const Vec2 lo = wing.section().extent_lo(), hi = wing.section().extent_hi();
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (double v : {0.0, p.span}) {
    const double c = wing.chord_at(v), x0 = wing.leading_edge_x(v);
    xmin = std::min(xmin, x0 + c * lo.x());
    xmax = std::max(xmax, x0 + c * hi.x());
    ymin = std::min(ymin, c * lo.y());
    ymax = std::max(ymax, c * hi.y());
  }
  double zmax = p.span;
  if (p.round_tip) {  // the rounded cap above z = span, sampled (it leans with sweep and taper)
    const RoundTipMap tip(std::make_shared<const NacaWing>(wing));
    for (int i = 0; i <= kCapSamples; ++i)
      for (int j = 0; j <= kCapSamples; ++j) {
        const Vec3 x = tip.point(static_cast<double>(i) / kCapSamples, kPi * j / kCapSamples);
        xmin = std::min(xmin, x.x()), xmax = std::max(xmax, x.x()), zmax = std::max(zmax, x.z());
        ymin = std::min(ymin, x.y()), ymax = std::max(ymax, x.y());
      }
  }
  if (!(b[0] < xmin && b[3] > xmax && b[1] < ymin && b[4] > ymax && b[5] > zmax))
    reject("naca.box", box_text(b),
           "xmin,ymin,zmin,xmax,ymax,zmax strictly enclosing the wing, which spans x [" + number(xmin) + ", " + number(xmax) +
               "], y [" + number(ymin) + ", " + number(ymax) + "], z [0, " + number(zmax) + "]");
}

}  // namespace semimesh::mock_cad::detail
