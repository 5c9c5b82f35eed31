// Assembles the wing, wall and box entities into a cad::Model (topology and loop orientation:
// see the comment at the top of naca.hpp and the contract in cadapi/model.hpp).
#include "fuselage_root.hpp"
#include "fuselage_wall.hpp"
#include "naca_validation.hpp"
#include "naca_wing.hpp"
#include "plane_entities.hpp"
#include "revolution_entities.hpp"
#include "round_tip_entities.hpp"
#include "wing_entities.hpp"

#include "semimesh/cad/error.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <map>

namespace semimesh::mock_cad {
namespace {

using cad::CurveUse;
using cad::Interval;
using cad::Loop;
using cad::Vec3;
using detail::RootPart;
using detail::Side;

// Convergence tolerance of projections and the band around face boundaries that counts as
// inside, both relative to the root chord.
constexpr double kSolverTolerance = 1e-12;
constexpr double kBoundaryBand = 1e-10;

CurveUse fwd(int curve) { return CurveUse{curve, true}; }
CurveUse rev(int curve) { return CurveUse{curve, false}; }

class Builder {
 public:
  explicit Builder(const NacaWingParams& p)
      : p_(p),
        wing_(std::make_shared<const detail::NacaWing>(detail::NacaSection(detail::parse_naca_code(p.code), p.sharp_te),
                                                       p.chord, p.span, p.taper, p.sweep_deg, p.dihedral_deg)),
        tip_(p.round_tip ? std::make_shared<const detail::RoundTipMap>(wing_) : nullptr),
        slope_(std::tan(p.wall_angle_deg * M_PI / 180.0)),
        root_(p.fuselage ? std::make_shared<const detail::FuselageRoot>(wing_, p.wall_radius, slope_) : nullptr),
        model_(std::make_unique<cad::Model>("naca")),
        tol_(kSolverTolerance * p.chord),
        band_(kBoundaryBand * p.chord) {}

  std::unique_ptr<cad::Model> build() {
    add_wing_curves();
    if (p_.farfield) add_box_curves();
    if (p_.farfield && root_) add_fuselage_curves();
    add_wing_surfaces();
    if (p_.farfield && root_) add_fuselage_farfield_surfaces();
    else if (p_.farfield) add_farfield_surfaces();
    model_->set_units(p_.units, 1.0);
    model_->set_units_origin("naca.units (the generated wing's lengths; its chord is naca.chord)");
    model_->set_tolerance(tol_);
    model_->set_thread_safe(true);
    model_->finalize();
    return std::move(model_);
  }

 private:
  int vertex(const std::string& name, const Vec3& point) { return vertices_[name] = model_->add_vertex(point, name); }

  int line(const std::string& name, const std::string& from, const std::string& to, Interval range) {
    const int a = vertices_.at(from), b = vertices_.at(to);
    auto curve = std::make_unique<detail::LineCurve>(model_->num_curves(), name, model_->vertex(a).point,
                                                     model_->vertex(b).point, range);
    return curves_[name] = model_->add_curve(std::move(curve), a, b);
  }

  int section(const std::string& name, Side side, double v, const std::string& from, const std::string& to) {
    auto curve = std::make_unique<detail::SectionCurve>(model_->num_curves(), name, wing_, side, v, tol_);
    return curves_[name] = model_->add_curve(std::move(curve), vertices_.at(from), vertices_.at(to));
  }

  // On the wall: z = 0 on the plane, the root height on the cylinder.
  Vec3 root_point(Side side, double u) const {
    return root_ ? root_->point(side == Side::Upper ? RootPart::Upper : RootPart::Lower, u, 0.0) : wing_->point(side, u, 0.0);
  }

  // A root curve: the section z = 0 on the plane, the intersection with the cylinder on it.
  void root_section(const std::string& name, Side side, const std::string& from, const std::string& to) {
    if (!root_) {
      section(name, side, 0.0, from, to);
      return;
    }
    const RootPart part = side == Side::Upper ? RootPart::Upper : RootPart::Lower;
    curves_[name] = model_->add_curve(std::make_unique<detail::RootCurve>(model_->num_curves(), name, root_, part, tol_),
                                      vertices_.at(from), vertices_.at(to));
  }

  void add_wing_curves() {
    const double span = p_.span;
    vertex("root_le", root_point(Side::Upper, 0.0));
    vertex("tip_le", wing_->point(Side::Upper, 0.0, span));
    if (p_.sharp_te) {
      vertex("root_te", root_point(Side::Upper, 1.0));
      vertex("tip_te", wing_->point(Side::Upper, 1.0, span));
    } else {
      vertex("root_te_upper", root_point(Side::Upper, 1.0));
      vertex("root_te_lower", root_point(Side::Lower, 1.0));
      vertex("tip_te_upper", wing_->point(Side::Upper, 1.0, span));
      vertex("tip_te_lower", wing_->point(Side::Lower, 1.0, span));
    }
    const std::string te_upper_root = p_.sharp_te ? "root_te" : "root_te_upper";
    const std::string te_lower_root = p_.sharp_te ? "root_te" : "root_te_lower";
    const std::string te_upper_tip = p_.sharp_te ? "tip_te" : "tip_te_upper";
    const std::string te_lower_tip = p_.sharp_te ? "tip_te" : "tip_te_lower";

    line("leading_edge", "root_le", "tip_le", Interval{0.0, span});
    root_section("root_upper", Side::Upper, "root_le", te_upper_root);
    root_section("root_lower", Side::Lower, "root_le", te_lower_root);
    section("tip_upper", Side::Upper, span, "tip_le", te_upper_tip);
    section("tip_lower", Side::Lower, span, "tip_le", te_lower_tip);
    if (p_.sharp_te) {
      line("trailing_edge", "root_te", "tip_te", Interval{0.0, span});
    } else {
      line("te_upper", "root_te_upper", "tip_te_upper", Interval{0.0, span});
      line("te_lower", "root_te_lower", "tip_te_lower", Interval{0.0, span});
      if (root_)
        curves_["root_te"] = model_->add_curve(
            std::make_unique<detail::RootCurve>(model_->num_curves(), "root_te", root_, RootPart::Base, tol_),
            vertices_.at("root_te_lower"), vertices_.at("root_te_upper"));
      else
        line("root_te", "root_te_lower", "root_te_upper", Interval{0.0, 1.0});
      if (tip_)
        curves_["tip_te"] = model_->add_curve(std::make_unique<detail::TipArc>(model_->num_curves(), "tip_te", tip_, tol_),
                                              vertices_.at("tip_te_lower"), vertices_.at("tip_te_upper"));
      else
        line("tip_te", "tip_te_lower", "tip_te_upper", Interval{0.0, 1.0});
    }
    if (tip_) {
      pole("tip_le_pole", "tip_le");
      if (p_.sharp_te) pole("tip_te_pole", "tip_te");
    }
  }

  // A pole of the rounded tip: t = phi in [0, pi].
  void pole(const std::string& name, const std::string& at) {
    const int v = vertices_.at(at);
    curves_[name] = model_->add_curve(
        std::make_unique<detail::PoleCurve>(model_->num_curves(), name, model_->vertex(v).point, Interval{0.0, M_PI}), v, v);
  }

  static std::string corner(int i, int j, int k) {
    return std::string("box_") + (i ? "xmax" : "xmin") + (j ? "_ymax" : "_ymin") + (k ? "_zmax" : "_zmin");
  }

  void add_box_curves() {
    const auto& b = p_.box;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) vertex(corner(i, j, k), Vec3(b[3 * i], b[1 + 3 * j], b[2 + 3 * k]));
    auto tag = [](const char* axis, int side) { return std::string(axis) + (side ? "max" : "min"); };
    for (int j = 0; j < 2; ++j)  // along x
      for (int k = 0; k < 2; ++k)
        line("box_" + tag("y", j) + "_" + tag("z", k), corner(0, j, k), corner(1, j, k), Interval{b[0], b[3]});
    for (int i = 0; i < 2; ++i)  // along y
      for (int k = 0; k < 2; ++k)
        line("box_" + tag("x", i) + "_" + tag("z", k), corner(i, 0, k), corner(i, 1, k), Interval{b[1], b[4]});
    for (int i = 0; i < 2; ++i)  // along z
      for (int j = 0; j < 2; ++j)
        line("box_" + tag("x", i) + "_" + tag("y", j), corner(i, j, 0), corner(i, j, 1), Interval{b[2], b[5]});
  }

  // The fuselage: its bottom line (the wall's seam, t = x) and its circles at the box's ends (t = phi),
  // which start and end on that line (fuselage_wall.hpp).
  void add_fuselage_curves() {
    const double r = p_.wall_radius, x0 = p_.box[0], x1 = p_.box[3];
    for (const auto& [name, x] : {std::pair<std::string, double>{"wall_xmin", x0}, {"wall_xmax", x1}})
      vertex(name, Vec3(x, 0.0, -r - (r + slope_ * x)));
    line("wall_seam", "wall_xmin", "wall_xmax", Interval{x0, x1});
    for (const auto& [name, x] : {std::pair<std::string, double>{"wall_xmin", x0}, {"wall_xmax", x1}})
      curves_[name] = model_->add_curve(std::make_unique<detail::FuselageCircle>(model_->num_curves(), name, x, r + slope_ * x, r),
                                        vertices_.at(name), vertices_.at(name));
  }

  int c(const std::string& name) const { return curves_.at(name); }

  void surface(std::unique_ptr<cad::Surface> s, std::vector<Loop> loops) { model_->add_surface(std::move(s), std::move(loops)); }

  int next_surface() const { return model_->num_surfaces(); }

  void add_wing_surfaces() {
    const bool sharp = p_.sharp_te;
    const int te_up = sharp ? c("trailing_edge") : c("te_upper");
    const int te_lo = sharp ? c("trailing_edge") : c("te_lower");
    // Loops run counter-clockwise around the fluid normal (material on the left).
    surface(std::make_unique<detail::WingSkin>(next_surface(), "upper", wing_, Side::Upper, tol_, root_),
            {Loop{{fwd(c("leading_edge")), fwd(c("tip_upper")), rev(te_up), rev(c("root_upper"))}}});
    surface(std::make_unique<detail::WingSkin>(next_surface(), "lower", wing_, Side::Lower, tol_, root_),
            {Loop{{fwd(c("root_lower")), fwd(te_lo), rev(c("tip_lower")), rev(c("leading_edge"))}}});
    if (!sharp) {
      const Loop base_loop{{fwd(c("root_te")), fwd(c("te_upper")), rev(c("tip_te")), rev(c("te_lower"))}};
      if (tip_)
        surface(std::make_unique<detail::CappedTrailingEdgeBase>(next_surface(), "te_base", tip_, tol_), {base_loop});
      else
        surface(std::make_unique<detail::TrailingEdgeBase>(next_surface(), "te_base", wing_, tol_, root_), {base_loop});
    }
    if (tip_) {  // clockwise in (u, phi) (orientation -1): up the pole, along phi = pi, down u = 1, back
      const int te = sharp ? c("tip_te_pole") : c("tip_te");
      surface(std::make_unique<detail::RoundTipFace>(next_surface(), "tip", tip_, tol_),
              {Loop{{fwd(c("tip_le_pole")), fwd(c("tip_lower")), fwd(te), rev(c("tip_upper"))}}});
      return;
    }

    const double span = p_.span, chord = wing_->chord_at(span), x_le = wing_->leading_edge_x(span);
    const double y_le = wing_->leading_edge_y(span);
    const cad::Vec2 lo = wing_->section().extent_lo(), hi = wing_->section().extent_hi();
    const double pad = 1e-3 * chord;  // keeps the sampled section extents clear of the outline
    const std::array<Interval, 2> tip_box = {Interval{x_le + chord * lo.x() - pad, x_le + chord * hi.x() + pad},
                                             Interval{y_le + chord * lo.y() - pad, y_le + chord * hi.y() + pad}};
    Loop tip_loop = sharp ? Loop{{fwd(c("tip_lower")), rev(c("tip_upper"))}}
                          : Loop{{fwd(c("tip_lower")), fwd(c("tip_te")), rev(c("tip_upper"))}};
    surface(std::make_unique<detail::PlaneFace>(next_surface(), "tip", +1, Vec3(0, 0, span), Vec3::UnitX(), Vec3::UnitY(),
                                                tip_box, band_, detail::SectionTrim{wing_, span, true}),
            {tip_loop});
  }

  void add_farfield_surfaces() {
    const auto& b = p_.box;
    const Interval x{b[0], b[3]}, y{b[1], b[4]}, z{b[2], b[5]};
    const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
    auto plane = [&](const std::string& name, int orientation, const Vec3& origin, const Vec3& e1, const Vec3& e2,
                     Interval i1, Interval i2, std::vector<Loop> loops, std::optional<detail::SectionTrim> trim = {}) {
      surface(std::make_unique<detail::PlaneFace>(next_surface(), name, orientation, origin, e1, e2,
                                                  std::array<Interval, 2>{i1, i2}, band_, std::move(trim)),
              std::move(loops));
    };
    plane("wall", +1, Vec3::Zero(), ex, ey, x, y,
          {Loop{{fwd(c("box_ymin_zmin")), fwd(c("box_xmax_zmin")), rev(c("box_ymax_zmin")), rev(c("box_xmin_zmin"))}}, root_hole()},
          detail::SectionTrim{wing_, 0.0, false});
    // Box faces: normals point into the box (the fluid).
    plane("box_xmin", +1, Vec3(b[0], 0, 0), ey, ez, y, z,
          {Loop{{fwd(c("box_xmin_zmin")), fwd(c("box_xmin_ymax")), rev(c("box_xmin_zmax")), rev(c("box_xmin_ymin"))}}});
    plane("box_xmax", -1, Vec3(b[3], 0, 0), ey, ez, y, z,
          {Loop{{fwd(c("box_xmax_ymin")), fwd(c("box_xmax_zmax")), rev(c("box_xmax_ymax")), rev(c("box_xmax_zmin"))}}});
    plane("box_ymin", -1, Vec3(0, b[1], 0), ex, ez, x, z,
          {Loop{{fwd(c("box_xmin_ymin")), fwd(c("box_ymin_zmax")), rev(c("box_xmax_ymin")), rev(c("box_ymin_zmin"))}}});
    plane("box_ymax", +1, Vec3(0, b[4], 0), ex, ez, x, z,
          {Loop{{fwd(c("box_ymax_zmin")), fwd(c("box_xmax_ymax")), rev(c("box_ymax_zmax")), rev(c("box_xmin_ymax"))}}});
    plane("box_zmax", -1, Vec3(0, 0, b[5]), ex, ey, x, y,
          {Loop{{fwd(c("box_xmin_zmax")), fwd(c("box_ymax_zmax")), rev(c("box_xmax_zmax")), rev(c("box_ymin_zmax"))}}});
  }

  // The root section's loop, a hole of the wall: walked clockwise around the wall's normal (+z at
  // the root, on the plane and on the cylinder's crest).
  Loop root_hole() const {
    return p_.sharp_te ? Loop{{fwd(c("root_upper")), rev(c("root_lower"))}}
                       : Loop{{fwd(c("root_upper")), rev(c("root_te")), rev(c("root_lower"))}};
  }

  // naca.wall = cylinder or cone: the fuselage runs through the box, whose ends hold its circles as
  // holes and whose bottom is a face of its own.
  void add_fuselage_farfield_surfaces() {
    const auto& b = p_.box;
    const double r = p_.wall_radius;
    const Interval x{b[0], b[3]}, y{b[1], b[4]}, z{b[2], b[5]};
    const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
    // Counter-clockwise in (x, phi): along the seam at phi = 0, up the circle at xmax, back along
    // the seam at phi = 2 pi, down the circle at xmin.
    surface(std::make_unique<detail::FuselageWall>(next_surface(), "wall", wing_, r, slope_, x, band_),
            {Loop{{fwd(c("wall_seam")), fwd(c("wall_xmax")), rev(c("wall_seam")), rev(c("wall_xmin"))}}, root_hole()});
    auto plane = [&](const std::string& name, int orientation, const Vec3& origin, const Vec3& e1, const Vec3& e2,
                     Interval i1, Interval i2, std::vector<Loop> loops, std::optional<detail::DiscHole> hole = {}) {
      surface(std::make_unique<detail::PlaneFace>(next_surface(), name, orientation, origin, e1, e2,
                                                  std::array<Interval, 2>{i1, i2}, band_, std::nullopt, hole),
              std::move(loops));
    };
    // Box faces: normals point into the box. A circle runs clockwise around +x (fuselage_wall.hpp):
    // a hole of box_xmin (normal +x) forward, of box_xmax (normal -x) reversed.
    auto disc = [&](double x_end) { return detail::DiscHole{cad::Vec2(0.0, -r), r + slope_ * x_end}; };  // in (y, z)
    plane("box_xmin", +1, Vec3(b[0], 0, 0), ey, ez, y, z,
          {Loop{{fwd(c("box_xmin_zmin")), fwd(c("box_xmin_ymax")), rev(c("box_xmin_zmax")), rev(c("box_xmin_ymin"))}},
           Loop{{fwd(c("wall_xmin"))}}},
          disc(b[0]));
    plane("box_xmax", -1, Vec3(b[3], 0, 0), ey, ez, y, z,
          {Loop{{fwd(c("box_xmax_ymin")), fwd(c("box_xmax_zmax")), rev(c("box_xmax_ymax")), rev(c("box_xmax_zmin"))}},
           Loop{{rev(c("wall_xmax"))}}},
          disc(b[3]));
    plane("box_ymin", -1, Vec3(0, b[1], 0), ex, ez, x, z,
          {Loop{{fwd(c("box_xmin_ymin")), fwd(c("box_ymin_zmax")), rev(c("box_xmax_ymin")), rev(c("box_ymin_zmin"))}}});
    plane("box_ymax", +1, Vec3(0, b[4], 0), ex, ez, x, z,
          {Loop{{fwd(c("box_ymax_zmin")), fwd(c("box_xmax_ymax")), rev(c("box_ymax_zmax")), rev(c("box_xmin_ymax"))}}});
    plane("box_zmin", +1, Vec3(0, 0, b[2]), ex, ey, x, y,
          {Loop{{fwd(c("box_ymin_zmin")), fwd(c("box_xmax_zmin")), rev(c("box_ymax_zmin")), rev(c("box_xmin_zmin"))}}});
    plane("box_zmax", -1, Vec3(0, 0, b[5]), ex, ey, x, y,
          {Loop{{fwd(c("box_xmin_zmax")), fwd(c("box_ymax_zmax")), rev(c("box_xmax_zmax")), rev(c("box_ymin_zmax"))}}});
  }

  const NacaWingParams& p_;
  std::shared_ptr<const detail::NacaWing> wing_;
  std::shared_ptr<const detail::RoundTipMap> tip_;      // naca.tip = round only
  double slope_;                                        // the cone's dr/dx (0: a cylinder or the plane)
  std::shared_ptr<const detail::FuselageRoot> root_;    // naca.wall = cylinder only
  std::unique_ptr<cad::Model> model_;
  double tol_, band_;
  std::map<std::string, int> vertices_, curves_;
};

// The body of revolution: vertices nose, tail; curves meridian (seam), nose, tail (poles); one face
// whose loop runs clockwise in (u, w) (orientation -1): up the nose pole, along the seam at
// w = 2 pi, down the tail pole, back along the seam at w = 0.
std::unique_ptr<cad::Model> make_revolution_body(const NacaWingParams& p) {
  auto section = std::make_shared<const detail::NacaSection>(detail::parse_naca_code(p.code), true);
  auto model = std::make_unique<cad::Model>("naca");
  const double tol = kSolverTolerance * p.chord;
  const int nose = model->add_vertex(Vec3::Zero(), "nose");
  const int tail = model->add_vertex(p.chord * Vec3(section->point(Side::Upper, 1.0).x(), 0.0, 0.0), "tail");
  const int meridian = model->add_curve(std::make_unique<detail::MeridianCurve>(0, "meridian", section, p.chord), nose, tail);
  const int nose_pole = model->add_curve(std::make_unique<detail::PoleCurve>(1, "nose", model->vertex(nose).point), nose, nose);
  const int tail_pole = model->add_curve(std::make_unique<detail::PoleCurve>(2, "tail", model->vertex(tail).point), tail, tail);
  model->add_surface(std::make_unique<detail::RevolutionBody>(0, "body", section, p.chord, tol),
                     {Loop{{fwd(nose_pole), fwd(meridian), rev(tail_pole), rev(meridian)}}});
  model->set_units(p.units, 1.0);
  model->set_units_origin("naca.units (the generated body's lengths; its chord is naca.chord)");
  model->set_tolerance(tol);
  model->set_thread_safe(true);
  model->finalize();
  return model;
}

}  // namespace

std::unique_ptr<cad::Model> make_naca_wing(const NacaWingParams& params) {
  detail::validate(params);
  if (params.revolution) return make_revolution_body(params);
  return Builder(params).build();
}

std::unique_ptr<cad::Model> load_naca(const cad::Source& source) {
  if (!source.path.empty())
    throw cad::CadError(cad::CadError::Kind::BadParameter,
                        "backend 'naca' builds its wing from naca.* parameters and reads no file, but was given '" +
                            source.path + "' (use backend 'occ' for CAD files)");
  return make_naca_wing(naca_params_from(source.params));
}

}  // namespace semimesh::mock_cad
