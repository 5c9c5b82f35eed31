// The NACA wing on a wall in a far-field box as OCC geometry, same frame and parametrisation as
// the analytic backend (mock_cad/naca.hpp):
//   S(u, v) = (x_le(v) + c(v) X(u), c(v) Y(u), v),  c and x_le linear in v,  x = u^2 chordwise.
// The section (X, Y)(u) is a 2D B-spline: for a symmetric section X = u^2 and Y = +-y_t(u), a
// polynomial of degree 8 in u, written exactly in the Bernstein basis; a cambered section is a
// clamped cubic spline interpolating the exact profile (split at the maximum camber, where the
// camber line's curvature jumps). S is linear in v, so the skins are exact B-splines of degree
// (p, 1) with the section's poles scaled and shifted at the root and the tip.
// Profile formulas: Abbott & von Doenhoff, "Theory of Wing Sections" (1959), sec. 6.4.
#include "prepare_shape.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <ShapeFix_Face.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax3.hxx>

#include <cmath>
#include <vector>

namespace semimesh::occ {
namespace {

using cad::CadError;

constexpr double kPi = 3.14159265358979323846;
// Thickness coefficients a0..a3 and the two a4 (NACA Report 460): y_t in powers of u = sqrt(x).
constexpr double kA0 = 0.2969, kA1 = -0.1260, kA2 = -0.3516, kA3 = 0.2843;
constexpr double kA4Blunt = -0.1015, kA4Sharp = -0.1036;
constexpr int kFitIntervals = 160;  // per camber arc: cubic interpolation error ~1e-10 chord

struct Section {
  double m = 0, p = 0, t = 0, a4 = kA4Blunt;

  /// Half thickness as power-basis coefficients in u, degree 8.
  std::vector<double> thickness_coefficients() const {
    return {0, 5 * t * kA0, 5 * t * kA1, 0, 5 * t * kA2, 0, 5 * t * kA3, 0, 5 * t * a4};
  }
  /// (X, Y) and d/du of one side (+1 upper, -1 lower) at u.
  void eval(int side, double u, gp_Pnt2d& point, gp_Vec2d& d1) const {
    const double x = u * u;
    double yt = 0, yt_u = 0;
    const auto a = thickness_coefficients();
    for (int k = 8; k >= 0; --k) {
      yt_u = yt_u * u + yt;
      yt = yt * u + a[k];
    }
    double yc = 0, slope = 0, curvature = 0;  // y_c, dy_c/dx, d2y_c/dx2 (two parabolas)
    if (m > 0) {
      const double q = x < p ? p * p : (1 - p) * (1 - p);
      yc = x < p ? m / q * (2 * p * x - x * x) : m / q * ((1 - 2 * p) + 2 * p * x - x * x);
      slope = 2 * m / q * (p - x);
      curvature = -2 * m / q;
    }
    const double c = 1 / std::sqrt(1 + slope * slope), sin_t = slope * c, cos_t = c;
    const double theta_u = curvature * c * c * 2 * u;  // dtheta/dx * dx/du
    const double s = side;
    point.SetCoord(x - s * yt * sin_t, yc + s * yt * cos_t);
    d1.SetCoord(2 * u - s * (yt_u * sin_t + yt * cos_t * theta_u), slope * 2 * u + s * (yt_u * cos_t - yt * sin_t * theta_u));
  }
};

Section section_of(const mock_cad::NacaWingParams& params) {
  const std::string& code = params.code;
  if (code.size() != 4 || code.find_first_not_of("0123456789") != std::string::npos)
    throw CadError(CadError::Kind::BadParameter, "parameter 'naca.code' = '" + code + "': expected 4 digits MPTT");
  Section s;
  s.m = (code[0] - '0') / 100.0;
  s.p = (code[1] - '0') / 10.0;
  s.t = std::stoi(code.substr(2)) / 100.0;
  s.a4 = params.sharp_te ? kA4Sharp : kA4Blunt;
  if (s.m > 0 && (s.p <= 0 || s.p >= 1))
    throw CadError(CadError::Kind::BadParameter, "parameter 'naca.code' = '" + code + "': a cambered section needs 1 <= P <= 9");
  return s;
}

/// Power-basis coefficients a_k of a degree-n polynomial -> Bernstein coefficients on [0, 1]:
/// b_i = sum_{k <= i} C(i,k) / C(n,k) a_k.
std::vector<double> bernstein_from_power(const std::vector<double>& a) {
  const int n = static_cast<int>(a.size()) - 1;
  auto binomial = [](int top, int k) {
    double r = 1;
    for (int j = 1; j <= k; ++j) r = r * (top - k + j) / j;
    return r;
  };
  std::vector<double> b(n + 1, 0.0);
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k) b[i] += binomial(i, k) / binomial(n, k) * a[k];
  return b;
}

/// A 2D B-spline as poles, knots, multiplicities and degree.
struct Profile {
  std::vector<gp_Pnt2d> poles;
  std::vector<double> knots;
  std::vector<int> mults;
  int degree = 0;
};

Profile exact_symmetric_profile(const Section& section, int side) {
  std::vector<double> x_power(9, 0.0), y_power = section.thickness_coefficients();
  x_power[2] = 1.0;
  for (double& y : y_power) y *= side;
  const auto bx = bernstein_from_power(x_power), by = bernstein_from_power(y_power);
  Profile profile;
  for (int i = 0; i <= 8; ++i) profile.poles.emplace_back(bx[i], by[i]);
  profile.knots = {0.0, 1.0};
  profile.mults = {9, 9};
  profile.degree = 8;
  return profile;
}

/// Clamped cubic interpolation of the exact profile on [u0, u1] at the parameters u themselves.
Handle(Geom2d_BSplineCurve) fit_arc(const Section& section, int side, double u0, double u1) {
  Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, kFitIntervals + 1);
  Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, kFitIntervals + 1);
  gp_Vec2d d_first, d_last, d;
  for (int i = 0; i <= kFitIntervals; ++i) {
    const double u = u0 + (u1 - u0) * i / kFitIntervals;
    gp_Pnt2d p;
    section.eval(side, u, p, d);
    if (i == 0) d_first = d;
    if (i == kFitIntervals) d_last = d;
    points->SetValue(i + 1, p);
    params->SetValue(i + 1, u);
  }
  Geom2dAPI_Interpolate interpolate(points, params, Standard_False, 1e-15);
  interpolate.Load(d_first, d_last, Standard_False);
  interpolate.Perform();
  if (!interpolate.IsDone()) throw CadError(CadError::Kind::Geometry, "occ: fitting the cambered NACA section failed");
  return interpolate.Curve();
}

/// Two clamped cubic arcs joined C1 at u = sqrt(p) (knot of multiplicity 2).
Profile fitted_cambered_profile(const Section& section, int side) {
  const double u_split = std::sqrt(section.p);
  Profile profile;
  profile.degree = 3;
  const Handle(Geom2d_BSplineCurve) arcs[2] = {fit_arc(section, side, 0.0, u_split), fit_arc(section, side, u_split, 1.0)};
  for (int a = 0; a < 2; ++a) {
    const Handle(Geom2d_BSplineCurve)& arc = arcs[a];
    for (int i = (a == 0 ? 1 : 2); i <= arc->NbPoles(); ++i) profile.poles.push_back(arc->Pole(i));
    for (int k = (a == 0 ? 1 : 2); k <= arc->NbKnots(); ++k) {
      profile.knots.push_back(arc->Knot(k));
      int mult = arc->Multiplicity(k);
      if (a == 0 && k == arc->NbKnots()) mult = 3;  // joint: end of arc 0 (4) and start of arc 1 share one pole
      profile.mults.push_back(mult);
    }
  }
  return profile;
}

/// The skin of one side: the section's poles at the root (v = 0) and the tip (v = span).
Handle(Geom_BSplineSurface) skin(const Profile& profile, const mock_cad::NacaWingParams& params) {
  const int n = static_cast<int>(profile.poles.size());
  const double tan_sweep = std::tan(params.sweep_deg * kPi / 180.0);
  TColgp_Array2OfPnt poles(1, n, 1, 2);
  for (int j = 0; j < 2; ++j) {
    const double z = j * params.span, c = params.chord * (1 - (1 - params.taper) * j), x_le = z * tan_sweep;
    for (int i = 0; i < n; ++i)
      poles.SetValue(i + 1, j + 1, gp_Pnt(x_le + c * profile.poles[i].X(), c * profile.poles[i].Y(), z));
  }
  TColStd_Array1OfReal u_knots(1, static_cast<int>(profile.knots.size())), v_knots(1, 2);
  TColStd_Array1OfInteger u_mults(1, static_cast<int>(profile.mults.size())), v_mults(1, 2);
  for (size_t k = 0; k < profile.knots.size(); ++k) {
    u_knots.SetValue(static_cast<int>(k) + 1, profile.knots[k]);
    u_mults.SetValue(static_cast<int>(k) + 1, profile.mults[k]);
  }
  v_knots.SetValue(1, 0.0);
  v_knots.SetValue(2, params.span);
  v_mults.SetValue(1, 2);
  v_mults.SetValue(2, 2);
  return new Geom_BSplineSurface(poles, u_knots, v_knots, u_mults, v_mults, profile.degree, 1);
}

/// Bilinear TE base: s = 0 on the lower TE line, s = 1 on the upper one, v = z.
Handle(Geom_BSplineSurface) te_base(const Geom_BSplineSurface& upper, const Geom_BSplineSurface& lower, double span) {
  TColgp_Array2OfPnt poles(1, 2, 1, 2);
  for (int j = 1; j <= 2; ++j) {
    poles.SetValue(1, j, lower.Pole(lower.NbUPoles(), j));
    poles.SetValue(2, j, upper.Pole(upper.NbUPoles(), j));
  }
  TColStd_Array1OfReal u_knots(1, 2), v_knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  u_knots.SetValue(1, 0.0);
  u_knots.SetValue(2, 1.0);
  v_knots.SetValue(1, 0.0);
  v_knots.SetValue(2, span);
  mults.Init(2);
  return new Geom_BSplineSurface(poles, u_knots, v_knots, mults, mults, 1, 1);
}

/// Plane whose (u, v) are the coordinates `a` and `b` (0 = x, 1 = y, 2 = z) at coordinate
/// `fixed` = `value`.
Handle(Geom_Plane) axis_plane(int fixed, double value, int a, int b) {
  gp_Pnt origin(0, 0, 0);
  origin.SetCoord(fixed + 1, value);
  gp_Dir axes[3] = {gp::DX(), gp::DY(), gp::DZ()};
  gp_Dir normal = axes[a].Crossed(axes[b]);
  return new Geom_Plane(gp_Ax3(origin, normal, axes[a]));
}

TopoDS_Face checked_face(BRepBuilderAPI_MakeFace& maker, const char* name) {
  if (!maker.IsDone()) throw CadError(CadError::Kind::Geometry, std::string("occ: building the NACA face '") + name + "' failed");
  return maker.Face();
}

/// The section outline at height v as a closed wire: upper LE -> TE, TE base, lower TE -> LE.
TopoDS_Wire section_wire(const Handle(Geom_BSplineSurface)& upper, const Handle(Geom_BSplineSurface)& lower, double v,
                         bool sharp_te) {
  BRepBuilderAPI_MakeWire wire;
  TopoDS_Edge upper_edge = BRepBuilderAPI_MakeEdge(upper->VIso(v), 0.0, 1.0);
  TopoDS_Edge lower_edge = BRepBuilderAPI_MakeEdge(lower->VIso(v), 0.0, 1.0);
  wire.Add(upper_edge);
  if (!sharp_te) wire.Add(BRepBuilderAPI_MakeEdge(upper->Value(1.0, v), lower->Value(1.0, v)).Edge());
  wire.Add(lower_edge);
  if (!wire.IsDone()) throw CadError(CadError::Kind::Geometry, "occ: the NACA section outline does not close");
  return wire.Wire();
}

}  // namespace

std::vector<std::string> naca_wing_face_names(const mock_cad::NacaWingParams& params) {
  std::vector<std::string> names = {"upper", "lower"};
  if (!params.sharp_te) names.push_back("te_base");
  names.push_back("tip");
  if (params.farfield)
    for (const char* name : {"wall", "box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}) names.push_back(name);
  return names;
}

TopoDS_Shape make_naca_wing_shape(const mock_cad::NacaWingParams& params) {
  const Section section = section_of(params);
  auto profile = [&](int side) {
    return section.m == 0 ? exact_symmetric_profile(section, side) : fitted_cambered_profile(section, side);
  };
  const Handle(Geom_BSplineSurface) upper = skin(profile(+1), params), lower = skin(profile(-1), params);
  const double span = params.span;

  std::vector<TopoDS_Face> faces;
  BRepBuilderAPI_MakeFace upper_face(upper, 0.0, 1.0, 0.0, span, 1e-9);
  faces.push_back(checked_face(upper_face, "upper"));
  BRepBuilderAPI_MakeFace lower_face(lower, 0.0, 1.0, 0.0, span, 1e-9);
  faces.push_back(checked_face(lower_face, "lower"));
  if (!params.sharp_te) {
    BRepBuilderAPI_MakeFace base(te_base(*upper, *lower, span), 0.0, 1.0, 0.0, span, 1e-9);
    faces.push_back(checked_face(base, "te_base"));
  }
  BRepBuilderAPI_MakeFace tip(axis_plane(2, span, 0, 1), section_wire(upper, lower, span, params.sharp_te), Standard_True);
  faces.push_back(checked_face(tip, "tip"));

  if (params.farfield) {
    const auto& b = params.box;  // xmin, ymin, zmin, xmax, ymax, zmax
    BRepBuilderAPI_MakeFace wall(axis_plane(2, 0.0, 0, 1), b[0], b[3], b[1], b[4], 1e-9);
    wall.Add(section_wire(upper, lower, 0.0, params.sharp_te));
    faces.push_back(checked_face(wall, "wall"));
    BRepBuilderAPI_MakeFace xmin(axis_plane(0, b[0], 1, 2), b[1], b[4], b[2], b[5], 1e-9);
    faces.push_back(checked_face(xmin, "box_xmin"));
    BRepBuilderAPI_MakeFace xmax(axis_plane(0, b[3], 1, 2), b[1], b[4], b[2], b[5], 1e-9);
    faces.push_back(checked_face(xmax, "box_xmax"));
    BRepBuilderAPI_MakeFace ymin(axis_plane(1, b[1], 0, 2), b[0], b[3], b[2], b[5], 1e-9);
    faces.push_back(checked_face(ymin, "box_ymin"));
    BRepBuilderAPI_MakeFace ymax(axis_plane(1, b[4], 0, 2), b[0], b[3], b[2], b[5], 1e-9);
    faces.push_back(checked_face(ymax, "box_ymax"));
    BRepBuilderAPI_MakeFace zmax(axis_plane(2, b[5], 0, 1), b[0], b[3], b[1], b[4], 1e-9);
    faces.push_back(checked_face(zmax, "box_zmax"));
  }

  // Planar faces built from wires get their pcurves and hole orientation fixed here.
  for (TopoDS_Face& face : faces) {
    ShapeFix_Face fix(face);
    fix.Perform();
    face = fix.Face();
  }

  BRepBuilderAPI_Sewing sewing(1e-7 * params.chord);
  for (const TopoDS_Face& face : faces) sewing.Add(face);
  sewing.Perform();
  // Rebuild the shell in the analytic order: sewing does not keep the order faces were added in.
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (const TopoDS_Face& face : faces) {
    TopoDS_Shape sewn = sewing.ModifiedSubShape(face);
    if (sewn.IsNull()) throw CadError(CadError::Kind::Geometry, "occ: sewing the NACA wing lost a face");
    for (TopExp_Explorer f(sewing.SewedShape(), TopAbs_FACE); f.More(); f.Next())
      if (f.Current().IsSame(sewn)) { sewn = f.Current(); break; }  // with its orientation in the sewn shell
    builder.Add(shell, sewn);
  }
  if (params.farfield && has_free_edges(shell))
    throw CadError(CadError::Kind::Geometry, "occ: the sewn NACA wing shell is not closed");
  shell.Closed(params.farfield);

  // Orient the shell so the upper skin's normal points out of the wing (+y at mid-chord).
  const TopoDS_Face first = TopoDS::Face(TopoDS_Iterator(shell).Value());
  gp_Pnt p;
  gp_Vec du, dv;
  BRep_Tool::Surface(first)->D1(0.5, 0.5 * span, p, du, dv);
  const double up = du.Crossed(dv).Y() * (first.Orientation() == TopAbs_REVERSED ? -1 : 1);
  if (up < 0) shell.Reverse();

  if (!BRepCheck_Analyzer(shell).IsValid()) throw CadError(CadError::Kind::Geometry, "occ: the NACA wing shell is not valid (BRepCheck)");
  return shell;
}

}  // namespace semimesh::occ
