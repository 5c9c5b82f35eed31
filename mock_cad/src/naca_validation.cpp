#include "naca_validation.hpp"
#include "constants.hpp"

#include "fuselage_root.hpp"
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

constexpr int kCapSamples = 200;  // per parameter of the rounded tip, for its extent
constexpr int kRootSamples = 200;  // per root curve on a fuselage, for its extremes
// On a fuselage of radius R: R above this many root half thicknesses, the root no further round
// than 1 - cos(angle) = this from the crest (R / 4 under it on a cylinder), the box this fraction of
// the fuselage's radius clear of it.
constexpr double kRadiusOverThickness = 4.0;
constexpr double kLowestRoot = 0.25;
constexpr double kBoxMargin = 0.1;
constexpr double kMaxConeAngle = 30.0;  // degrees
constexpr double kSmallestEnd = 0.1;    // of R: the cone's radius at the box's ends, its apex outside
constexpr double kHighestRoot = 0.5;    // of the span: the highest root point on a cone

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

std::string wall_name(const NacaWingParams& p) { return p.wall_angle_deg == 0.0 ? "cylinder" : "cone"; }

// The wing on the fuselage of radius naca.wall_radius (naca.wall_angle for a cone): the root must
// sit near the crest, where it is the graph of a height over the section (fuselage_root.hpp) and
// the wall's trim test applies (fuselage_wall.cpp). Returns the lowest root height.
double check_fuselage(const NacaWingParams& p, const std::shared_ptr<const NacaWing>& wing) {
  const double r = p.wall_radius, angle = p.wall_angle_deg;
  const std::string on = " on naca.wall = " + wall_name(p);
  if (!(r > 0.0 && std::isfinite(r))) reject("naca.wall_radius", number(r), "a fuselage radius > 0");
  if (!(std::abs(angle) < kMaxConeAngle))
    reject("naca.wall_angle", number(angle), "a cone half angle in degrees with |angle| < " + number(kMaxConeAngle));
  if (p.round_tip) reject("naca.tip", "round", "flat" + on + " (the rounded tip is built on a plane wall only)");
  const Vec2 lo = wing->section().extent_lo(), hi = wing->section().extent_hi();
  const double half = p.chord * std::max(std::abs(lo.y()), std::abs(hi.y()));
  if (!(r > kRadiusOverThickness * half))
    reject("naca.wall_radius", number(r),
           "a radius above " + number(kRadiusOverThickness) + " times the root section's half thickness, i.e. > " +
               number(kRadiusOverThickness * half) + " for naca.code = " + p.code + " and naca.chord = " + number(p.chord) +
               " (the root must sit near the fuselage's crest)");
  // A taper above 1 narrows the planform below z = 0, down towards the fuselage's axis.
  const double taper_max = 1.0 + 0.5 * p.span / r;
  if (!(p.taper < taper_max))
    reject("naca.taper", number(p.taper),
           "a taper below 1 + 0.5 naca.span / naca.wall_radius = " + number(taper_max) + on +
               " (the planform extended down to the fuselage's axis must keep half the root chord)");
  const double slope = std::tan(angle * kPi / 180.0);
  const FuselageRoot root(wing, r, slope);
  double lowest = 0.0, highest = 0.0, widest = 0.0;  // heights, and angle from the crest (as 1 - cos)
  for (RootPart part : {RootPart::Upper, RootPart::Lower, RootPart::Base}) {
    if (part == RootPart::Base && p.sharp_te) continue;
    for (int i = 0; i <= kRootSamples; ++i) {
      const Vec3 x = root.point(part, static_cast<double>(i) / kRootSamples, 0.0);
      lowest = std::min(lowest, x.z());
      highest = std::max(highest, x.z());
      widest = std::max(widest, 1.0 - (x.z() + r) / (r + slope * x.x()));
    }
  }
  if (!(widest < kLowestRoot))
    reject("naca.wall_radius", number(r),
           "a radius on which the root stays near the crest (cos of its angle round the fuselage above " +
               number(1.0 - kLowestRoot) + ", it reaches " + number(1.0 - widest) + "); a larger radius or a thinner section");
  // The skins run from the root up to z = span (fuselage_root.hpp): a cone's crest must not lift
  // the root near the tip.
  if (!(highest < kHighestRoot * p.span))
    reject("naca.span", number(p.span),
           "a span above " + number(highest / kHighestRoot) + " on this cone, whose crest lifts the root to z = " +
               number(highest) + " (the root must stay below " + number(kHighestRoot) + " span); or a smaller naca.wall_angle");
  return lowest;
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
  if (!(std::abs(p.dihedral_deg) < 45.0))
    reject("naca.dihedral", number(p.dihedral_deg), "a dihedral angle in degrees with |dihedral| < 45");
  if (p.units.empty()) reject("naca.units", p.units, "a unit name (e.g. chord, m, mm)");
  if (p.revolution) {
    const std::string what = "for naca.shape = revolution";
    if (digits.max_camber > 0.0) reject("naca.code", p.code, "a symmetric code 00TT " + what);
    if (!p.sharp_te) reject("naca.te", "blunt", "sharp " + what + " (the tail is a pole)");
    if (p.farfield) reject("naca.farfield", "true", "false " + what + " (the body has no wall)");
    if (p.round_tip) reject("naca.tip", "round", "flat " + what + " (the body has no tip)");
    if (p.fuselage) reject("naca.wall", wall_name(p), "plane " + what + " (the body has no wall)");
    if (p.dihedral_deg != 0.0) reject("naca.dihedral", number(p.dihedral_deg), "0 " + what + " (the body has no span)");
    return;
  }
  // The rounded tip is built on a wing without dihedral (round_tip.hpp).
  if (p.round_tip && p.dihedral_deg != 0.0)
    reject("naca.dihedral", number(p.dihedral_deg), "0 with naca.tip = round (the rounded tip is built on a wing without dihedral)");
  const auto shared_wing = std::make_shared<const NacaWing>(NacaSection(digits, p.sharp_te), p.chord, p.span, p.taper,
                                                            p.sweep_deg, p.dihedral_deg);
  const double root_low = p.fuselage ? check_fuselage(p, shared_wing) : 0.0;
  if (!p.farfield) return;

  const auto& b = p.box;
  if (p.fuselage) {
    const double r = p.wall_radius, slope = std::tan(p.wall_angle_deg * kPi / 180.0);
    const double r0 = r + slope * b[0], r1 = r + slope * b[3], r_max = std::max(r0, r1), m = kBoxMargin * r_max;
    if (!(std::min(r0, r1) > kSmallestEnd * r))
      reject("naca.wall_angle", number(p.wall_angle_deg),
             "a half angle whose cone keeps a radius above " + number(kSmallestEnd) + " naca.wall_radius over the box's x range [" +
                 number(b[0]) + ", " + number(b[3]) + "] (it has " + number(std::min(r0, r1)) + " there)");
    if (!(b[2] < -r - r_max - m && b[1] < -r_max - m && b[4] > r_max + m))
      reject("naca.box", box_text(b),
             "ymin < " + number(-r_max - m) + ", ymax > " + number(r_max + m) + " and zmin < " + number(-r - r_max - m) +
                 ": the box must hold the " + wall_name(p) + " of naca.wall_radius = " + number(r) +
                 " (axis y = 0, z = -R, largest radius " + number(r_max) + " in the box) with a margin of 0.1 of that; its default is " +
                 box_text(fuselage_default_box(r, p.wall_angle_deg)));
  } else if (b[2] != 0.0) {
    reject("naca.box", box_text(b), "zmin = 0 (the wall is the plane z = 0), got zmin = " + number(b[2]));
  }
  // The wing is the ruled hull of its lowest (root) and tip sections (linear planform).
  const NacaWing& wing = *shared_wing;
  const Vec2 lo = wing.section().extent_lo(), hi = wing.section().extent_hi();
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (double v : {root_low, p.span}) {
    const double c = wing.chord_at(v), x0 = wing.leading_edge_x(v), y0 = wing.leading_edge_y(v);
    xmin = std::min(xmin, x0 + c * lo.x());
    xmax = std::max(xmax, x0 + c * hi.x());
    ymin = std::min(ymin, y0 + c * lo.y());
    ymax = std::max(ymax, y0 + c * hi.y());
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
               "], y [" + number(ymin) + ", " + number(ymax) + "], z [" + number(root_low) + ", " + number(zmax) + "]");
}

}  // namespace semimesh::mock_cad::detail
