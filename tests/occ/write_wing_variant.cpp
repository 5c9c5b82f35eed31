// Writes the occ backend's B-spline NACA wing as a third-party CAD file of one of the kinds users
// bring (issue "your own wing CAD as it comes"), for end-to-end tests of `init --cad` and `run`:
//
//   write_wing_variant VARIANT OUT.step|OUT.igs [naca.key=value ...]
//
//   asis    the shape as the backend builds it (with naca.farfield=false: the body alone, its root
//           section left open: free curves in the wall plane, as wing CAD is often exported);
//   nurbs   every face converted to a B-spline (BRepBuilderAPI_NurbsConvert), as many CAD tools
//           export: the wall and the box faces are planar B-splines, not planes;
//   capped  every open planar loop closed by a planar face and sewn on (with naca.farfield=false: a
//           closed body whose root is a planar cap, like the ONERA M6 file);
//   open_tip   the skin without its tip face (with naca.farfield=false: root and tip both open);
//   unsewn     every face moved by its own ~1e-5 chord and written as separate IGES trimmed faces
//              (OUT.igs) with an INCH unit flag on numbers that are the chord's (metres);
//   hemisphere the body standing on a planar B-spline wall disk (the root section its hole) inside a
//              hemisphere of 8 chords, the far field in the file (needs naca.farfield=false);
//   two_bodies two body-only wings side by side (bad input: needs naca.farfield=false);
//   no_body    a box and nothing in it (bad input).
//   fuselage   the body, sunk 0.3 chord into a circular cylinder of radius 1.5 chords whose axis
//              runs along x through z = -1.5 chords (a fuselage), fused to it, inside a box that the
//              fuselage crosses from end to end: the far field in the file, the wall a cylinder
//              (needs naca.farfield=false);
//   fuselage_bspline  the same on a B-spline body of revolution whose radius swells from 1.1 chords
//              at the box's ends to 1.5 at the wing (the wall falls away under the wake);
//   fuselage_dihedral the wing leaning 10 degrees sideways (dihedral) on the cylinder: the wall's
//              normal turns along the root and the junction's angles differ on each side;
//   fuselage_seam_on_crest the cylinder with its seam along its top, through the wing's root (bad
//              input: the root is then no hole of the wall).
//   fuselage_unjoined the wing sunk into the cylinder as for `fuselage`, the two solids side by side in
//              the file, not fused, no box: an assembly of overlapping parts as OpenVSP exports one
//              (needs naca.farfield=false);
//   fuselage_unjoined_fin the same with a second wing hanging from the fuselage's keel (turned half a
//              turn about its axis): three parts, which to join is the user's choice;
//   fuselage_bspline_unjoined the wing and the B-spline body of revolution of `fuselage_bspline`,
//              not joined, the body's seam along its crest through the wing's root (OpenVSP writes a
//              fuselage's seam along one of its sides);
//   fuselage_nosed_unjoined the same with a nose cone 8 chords ahead of the wing (0.05 chord at its
//              tip), inside the 10 chords init's box would reach: init's box ends where the body is
//              near-cylindrical, not across the cone.
//   fuselage_through the wing and its mirror image through the fuselage's axis fused into one solid
//              running through the cylinder (a full-span wing, as OpenVSP exports one), and the
//              cylinder: two parts; init makes a half model (the box's side on the plane through
//              the fuselage's axis).
//   cranked    a body-only wing with a crank (root cap as in `capped`): an inboard panel (z from 0 to
//              0.8 chord, leading-edge sweep 10 degrees, chord 1 -> 0.75) and an outboard panel (to
//              z = 2 chords, sweep 35 degrees, chord 0.75 -> 0.35), twisted about the quarter chord
//              0 -> -2 -> -5 degrees (washout); each panel's upper, lower [and trailing-edge base]
//              surface its own B-spline face (the naca.code section, naca.te), meeting at the kink;
//              a planar tip face. naca.chord scales it; in the file's numbers as given (unit MM);
//   cranked_mm, cranked_m  the same wing at a root chord of 1 m (naca.chord ignored): written in
//              millimetres (numbers 1000, unit MM) and in metres (numbers 1, unit M).
//   split_base a body-only wing of chord 1 and span 1 (naca.chord scales it; root capped as in
//              `capped`) built as one `cranked` panel, its trailing-edge base split along the span at
//              mid-thickness into a lower and an upper half face, as OpenVSP writes a blunt base;
//   cranked_split_base  the cranked wing with each panel's base split so (a 2 x 2 base of faces).
//   pinched_tip a body-only wing (chord 1, span 1, root open in the wall plane z = 0) whose NACA 0012
//              section thins from 0.75 span to zero thickness at the tip, an upper and a lower
//              B-spline face through grids of its points: the tip is a knife edge, the two faces'
//              last iso-lines the same chord line (as OpenVSP closes a wing); naca.chord scales it.
//   seam_skin  a body-only wing (chord 1, span 1, root and tip open) whose skin is one face closed
//              round its NACA 0012 sections, its seam the sharp trailing edge (as OpenVSP writes a
//              wing component);
//   bezier_patches  the body with its root capped (as `capped`), every B-spline skin face rewritten
//              as 6 x 6 Bezier patches the way OpenVSP exports a wing: knots inserted at full
//              multiplicity (the geometry unchanged) and the patches' parameter lengths cycling
//              1 : 8 : 3, so the parametric speed jumps up to 8x at every joint (smooth geometry,
//              kinked parameters).
//
// Exit 0 on success, 1 with a message on stderr otherwise.
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Geom_BSplineSurface.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <Interface_Static.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BRepTools.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <utility>
#include <vector>
#include <TColStd_Array1OfReal.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <GC_MakeCircle.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Circ.hxx>
#include <gp_Trsf.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <cmath>
#include <iostream>
#include <string>

namespace {

TopoDS_Shape capped(const TopoDS_Shape& shape) {
  ShapeAnalysis_FreeBounds bounds(shape, 1e-7, /*splitclosed=*/false, /*splitopen=*/true);
  BRepBuilderAPI_Sewing sewing(1e-7);
  sewing.Add(shape);
  for (TopExp_Explorer w(bounds.GetClosedWires(), TopAbs_WIRE); w.More(); w.Next())
    sewing.Add(BRepBuilderAPI_MakeFace(TopoDS::Wire(w.Current()), /*OnlyPlane=*/true).Face());
  sewing.Perform();
  return sewing.SewedShape();
}

// The shape's faces in the generator's order (upper, lower, [te_base], tip, [wall, box...]).
std::vector<TopoDS_Face> faces_of(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) faces.push_back(TopoDS::Face(f.Current()));
  return faces;
}

TopoDS_Compound compound_of(const std::vector<TopoDS_Shape>& shapes) {
  TopoDS_Compound out;
  BRep_Builder builder;
  builder.MakeCompound(out);
  for (const TopoDS_Shape& s : shapes) builder.Add(out, s);
  return out;
}

TopoDS_Shape moved(const TopoDS_Shape& shape, const gp_Vec& by) {
  gp_Trsf move;
  move.SetTranslation(by);
  return BRepBuilderAPI_Transform(shape, move, /*copy=*/true).Shape();
}

TopoDS_Shape without_tip(const TopoDS_Shape& wing, const semimesh::mock_cad::NacaWingParams& params) {
  const std::vector<TopoDS_Face> faces = faces_of(wing);
  const std::size_t tip = params.sharp_te ? 2 : 3;
  std::vector<TopoDS_Shape> kept;
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (i != tip) kept.push_back(faces[i]);
  BRepBuilderAPI_Sewing sewing(1e-7);
  for (const TopoDS_Shape& f : kept) sewing.Add(f);
  sewing.Perform();
  return sewing.SewedShape();
}

// Each face moved by its own vector of length 1e-5 chord: edges that no longer meet, as faces
// exported one by one from a CAD tool do.
TopoDS_Shape unsewn(const TopoDS_Shape& wing, double chord) {
  std::vector<TopoDS_Shape> faces;
  int i = 0;
  for (const TopoDS_Face& f : faces_of(wing)) {
    const double a = 1.3 * ++i;
    faces.push_back(moved(f, gp_Vec(std::cos(a), std::sin(a), 0.5 * std::cos(2 * a)).Normalized() * (1e-5 * chord)));
  }
  return compound_of(faces);
}

// The root section: the body's free loop in the plane z = 0.
TopoDS_Wire root_loop(const TopoDS_Shape& body) {
  ShapeAnalysis_FreeBounds bounds(body, 1e-7, /*splitclosed=*/false, /*splitopen=*/true);
  for (TopExp_Explorer w(bounds.GetClosedWires(), TopAbs_WIRE); w.More(); w.Next()) {
    bool at_root = true;
    for (TopExp_Explorer v(w.Current(), TopAbs_VERTEX); v.More(); v.Next())
      at_root = at_root && std::abs(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())).Z()) < 1e-9;
    if (at_root) return TopoDS::Wire(w.Current());
  }
  throw std::invalid_argument("hemisphere: the body has no open root loop (use naca.farfield=false)");
}

TopoDS_Shape in_hemisphere(const TopoDS_Shape& body, double chord) {
  const double radius = 8.0 * chord;
  const gp_Ax2 axis(gp_Pnt(0.5 * chord, 0, 0), gp::DZ());
  const TopoDS_Edge rim = BRepBuilderAPI_MakeEdge(GC_MakeCircle(gp_Circ(axis, radius)).Value()).Edge();
  BRepBuilderAPI_MakeFace disk(new Geom_Plane(gp_Ax3(axis)), BRepBuilderAPI_MakeWire(rim).Wire(), Standard_True);
  disk.Add(TopoDS::Wire(root_loop(body).Reversed()));
  ShapeFix_Face fix(disk.Face());
  fix.Perform();
  const TopoDS_Shape wall = BRepBuilderAPI_NurbsConvert(fix.Face(), /*Copy=*/true).Shape();
  const TopoDS_Face dome = BRepBuilderAPI_MakeFace(new Geom_SphericalSurface(gp_Ax3(axis), radius), 0.0, 2 * M_PI,
                                                   0.0, M_PI / 2, 1e-9).Face();
  BRepBuilderAPI_Sewing sewing(1e-7 * chord);
  sewing.Add(body);
  sewing.Add(wall);
  sewing.Add(dome);
  sewing.Perform();
  return sewing.SewedShape();
}

enum class Fuselage { Cylinder, BSpline, Dihedral, SeamOnCrest, Nosed };

// A fuselage of radius 1.5 chords at the wing, its axis along x through z = -1.5 chords, running
// 24 chords (through the box): a cylinder, or a B-spline body of revolution swelling from 1.1
// chords at its ends to 1.5 at the wing. The seam at the bottom (the axis system's x direction
// -z), away from the root, unless asked on the crest. Nosed: the B-spline body with a nose cone
// from 0.05 chord at x = -8 chords to 1.4 at -4, the wing's box (10 chords) reaching past it.
TopoDS_Shape fuselage_solid(Fuselage kind, double chord, bool spline_seam_on_crest = false) {
  const double radius = 1.5 * chord, length = 24 * chord, start = -0.5 * length + 0.5 * chord;
  const gp_Ax2 axis(gp_Pnt(start, 0, -radius), gp::DX(), kind == Fuselage::SeamOnCrest ? gp::DZ() : -gp::DZ());
  if (kind != Fuselage::BSpline && kind != Fuselage::Nosed) return BRepPrimAPI_MakeCylinder(axis, radius, length).Shape();
  // The profile in the plane y = 0 below the axis (the revolution's seam), parallel to the axis at
  // its ends (the box's faces there meet the wall square, as the wall layer needs), revolved a
  // full turn, then made a B-spline.
  const bool nosed = kind == Fuselage::Nosed;
  const std::vector<double> xs = nosed ? std::vector<double>{-8 * chord, -6 * chord, -4 * chord, 0.0, chord, 5 * chord,
                                                             start + length}
                                       : std::vector<double>{start, -5 * chord, 0.0, chord, 5 * chord, start + length};
  const std::vector<double> rs = nosed ? std::vector<double>{0.05, 1.0, 1.4, 1.5, 1.5, 1.4, 1.1}
                                       : std::vector<double>{1.1, 1.4, 1.5, 1.5, 1.4, 1.1};
  const int n = static_cast<int>(xs.size());
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
  // The profile below the axis (the seam at the bottom) or above it (the seam on the crest).
  const double side = spline_seam_on_crest ? 1.0 : -1.0;
  for (int i = 0; i < n; ++i) points->SetValue(i + 1, gp_Pnt(xs[i], 0, -radius + side * rs[i] * chord));
  GeomAPI_Interpolate interpolate(points, /*PeriodicFlag=*/false, 1e-9);
  interpolate.Load(gp_Vec(1, 0, 0), gp_Vec(1, 0, 0));
  interpolate.Perform();
  const Handle(Geom_BSplineCurve) profile = interpolate.Curve();
  const gp_Pnt a(xs.front(), 0, -radius), b(xs.back(), 0, -radius);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(a, profile->StartPoint()).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(profile).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(profile->EndPoint(), b).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(b, a).Edge());
  const TopoDS_Face section = BRepBuilderAPI_MakeFace(wire.Wire(), /*OnlyPlane=*/true).Face();
  gp_Ax1 turn(a, gp::DX());
  const TopoDS_Shape revolved = BRepPrimAPI_MakeRevol(section, turn, 2 * M_PI).Shape();
  return BRepBuilderAPI_NurbsConvert(revolved, /*Copy=*/true).Shape();
}

// The wing as a solid, capped and moved down so that its root section lies inside the fuselage
// (radius 1.5 chords, its crest at z = 0), leaning sideways for Fuselage::Dihedral.
TopoDS_Shape sunk_wing(const TopoDS_Shape& body, double chord, Fuselage kind, double sunk_chords = 0.3) {
  const double sunk = sunk_chords * chord;
  TopoDS_Shell skin;
  for (TopExp_Explorer shell(capped(body), TopAbs_SHELL); shell.More(); shell.Next()) skin = TopoDS::Shell(shell.Current());
  ShapeFix_Solid solid;
  TopoDS_Shape wing = moved(solid.SolidFromShell(skin), gp_Vec(0, 0, -sunk));
  if (kind == Fuselage::Dihedral) {  // leaning about the root's line on the crest
    gp_Trsf lean;
    lean.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp::DX()), 10 * M_PI / 180);
    wing = BRepBuilderAPI_Transform(wing, lean, /*copy=*/true).Shape();
  }
  return wing;
}

// A wing-fuselage model: the box minus (wing sunk into the fuselage, fused to it). The wing is
// capped and moved down so that its root section lies inside the fuselage: the Boolean finds the
// root curve, the exact intersection of the skin with the fuselage.
TopoDS_Shape on_fuselage(const TopoDS_Shape& body, double chord, Fuselage kind) {
  const double radius = 1.5 * chord;
  BRepAlgoAPI_Fuse fused(sunk_wing(body, chord, kind), fuselage_solid(kind, chord));
  if (!fused.IsDone()) throw std::runtime_error("fuselage: the Boolean fuse of wing and cylinder failed");
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(-10 * chord, -10 * chord, -radius - 10 * chord),
                                               gp_Pnt(11 * chord, 10 * chord, 10 * chord)).Shape();
  BRepAlgoAPI_Cut fluid(box, fused.Shape());
  if (!fluid.IsDone()) throw std::runtime_error("fuselage: the Boolean cut of the box failed");
  // Its shell, as a closed shell's faces are read: bounding the fluid (a solid is read as a body).
  TopExp_Explorer shell(fluid.Shape(), TopAbs_SHELL);
  if (!shell.More()) throw std::runtime_error("fuselage: the Boolean cut left no shell");
  return shell.Current();
}

// The cranked wing's sections (issue #23: several spanwise faces meeting at a kink): the leading
// edge's x, the chord and the twist (degrees, nose up, about the quarter chord) at each z, in root
// chords.
struct CrankSection {
  double z, x_le, chord, twist_deg;
};
const CrankSection kCrank[] = {{0.0, 0.0, 1.0, 0.0},
                               {0.8, 0.8 * std::tan(10 * M_PI / 180), 0.75, -2.0},
                               {2.0, 0.8 * std::tan(10 * M_PI / 180) + 1.2 * std::tan(35 * M_PI / 180), 0.35, -5.0}};

// A pole (X, Y) of the unit section placed at a crank section: twisted about its quarter chord,
// scaled by its chord (and the root chord), shifted to its leading edge.
gp_Pnt placed(const gp_Pnt& unit, const CrankSection& at, double root_chord) {
  const double t = at.twist_deg * M_PI / 180, dx = unit.X() - 0.25, y = unit.Y();
  const double x = 0.25 + dx * std::cos(t) + y * std::sin(t), yr = -dx * std::sin(t) + y * std::cos(t);
  return gp_Pnt(root_chord * (at.x_le + at.chord * x), root_chord * at.chord * yr, root_chord * at.z);
}

// The skin between two sections: the unit wing's skin (its root row of poles is the section,
// exact) with each row placed at one section; ruled (degree 1) across the span as the NACA skins.
Handle(Geom_BSplineSurface) crank_panel(const Geom_BSplineSurface& unit, const CrankSection& a, const CrankSection& b,
                                        double root_chord) {
  TColgp_Array2OfPnt poles(1, unit.NbUPoles(), 1, 2);
  for (int i = 1; i <= unit.NbUPoles(); ++i) {
    poles.SetValue(i, 1, placed(unit.Pole(i, 1), a, root_chord));
    poles.SetValue(i, 2, placed(unit.Pole(i, 1), b, root_chord));
  }
  TColStd_Array1OfReal u_knots(1, unit.NbUKnots()), v_knots(1, 2);
  TColStd_Array1OfInteger u_mults(1, unit.NbUKnots()), v_mults(1, 2);
  unit.UKnots(u_knots);
  unit.UMultiplicities(u_mults);
  v_knots.SetValue(1, 0.0);
  v_knots.SetValue(2, 1.0);
  v_mults.Init(2);
  return new Geom_BSplineSurface(poles, u_knots, v_knots, u_mults, v_mults, unit.UDegree(), 1);
}

// The bilinear trailing-edge base between the two skins' last pole columns, from `from` to `to`
// across it (0: the lower skin's edge, 1: the upper's): [0, 1] whole, [0, 0.5] and [0.5, 1] its
// lower and upper halves, split along the span at mid-thickness as OpenVSP writes a blunt base.
Handle(Geom_BSplineSurface) crank_te_base(const Geom_BSplineSurface& upper, const Geom_BSplineSurface& lower,
                                          double from = 0.0, double to = 1.0) {
  TColgp_Array2OfPnt poles(1, 2, 1, 2);
  for (int j = 1; j <= 2; ++j) {
    const gp_XYZ a = lower.Pole(lower.NbUPoles(), j).XYZ(), b = upper.Pole(upper.NbUPoles(), j).XYZ();
    poles.SetValue(1, j, gp_Pnt(a + from * (b - a)));
    poles.SetValue(2, j, gp_Pnt(a + to * (b - a)));
  }
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  mults.Init(2);
  return new Geom_BSplineSurface(poles, knots, knots, mults, mults, 1, 1);
}

Handle(Geom_BSplineSurface) surface_of(const TopoDS_Face& face) {
  Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
  if (s.IsNull()) throw std::runtime_error("cranked: the unit wing's skin is not a B-spline surface");
  return s;
}

// The straight wing of chord 1 and span 1 as one panel between two crank sections.
const CrankSection kStraight[] = {{0.0, 0.0, 1.0, 0.0}, {1.0, 0.0, 1.0, 0.0}};

// The trailing-edge base of a panel: one face, or its lower and upper halves (split_base).
void add_te_base(BRepBuilderAPI_Sewing& sewing, const Geom_BSplineSurface& upper, const Geom_BSplineSurface& lower,
                 bool split_base) {
  if (!split_base) {
    sewing.Add(BRepBuilderAPI_MakeFace(crank_te_base(upper, lower), 1e-9).Face());
    return;
  }
  sewing.Add(BRepBuilderAPI_MakeFace(crank_te_base(upper, lower, 0.0, 0.5), 1e-9).Face());
  sewing.Add(BRepBuilderAPI_MakeFace(crank_te_base(upper, lower, 0.5, 1.0), 1e-9).Face());
}

// A body-only wing of panels between `sections` (its root capped), each panel's skins and base
// their own faces, the base split in halves with `split_base`; a planar tip face.
TopoDS_Shape paneled(const semimesh::mock_cad::NacaWingParams& params, const CrankSection* sections, int panels,
                     bool split_base) {
  semimesh::mock_cad::NacaWingParams unit = params;  // the section's poles at chord 1, z = 0
  unit.chord = 1;
  unit.span = 1;
  unit.taper = 1;
  unit.sweep_deg = unit.dihedral_deg = 0;
  unit.farfield = false;
  const std::vector<TopoDS_Face> unit_faces = faces_of(semimesh::occ::make_naca_wing_shape(unit));
  const Handle(Geom_BSplineSurface) unit_upper = surface_of(unit_faces[0]), unit_lower = surface_of(unit_faces[1]);
  BRepBuilderAPI_Sewing sewing(1e-7 * params.chord);
  Handle(Geom_BSplineSurface) upper, lower;
  for (int panel = 0; panel < panels; ++panel) {
    upper = crank_panel(*unit_upper, sections[panel], sections[panel + 1], params.chord);
    lower = crank_panel(*unit_lower, sections[panel], sections[panel + 1], params.chord);
    sewing.Add(BRepBuilderAPI_MakeFace(upper, 1e-9).Face());
    sewing.Add(BRepBuilderAPI_MakeFace(lower, 1e-9).Face());
    if (!params.sharp_te) add_te_base(sewing, *upper, *lower, split_base);
  }
  // The tip: the outboard panel's last section, a planar face.
  BRepBuilderAPI_MakeWire outline;
  outline.Add(BRepBuilderAPI_MakeEdge(upper->VIso(1.0)).Edge());
  const gp_Pnt te_upper = upper->Value(1, 1), te_lower = lower->Value(1, 1);
  const gp_Pnt te_middle(0.5 * (te_upper.XYZ() + te_lower.XYZ()));
  if (!params.sharp_te && split_base) {
    outline.Add(BRepBuilderAPI_MakeEdge(te_upper, te_middle).Edge());
    outline.Add(BRepBuilderAPI_MakeEdge(te_middle, te_lower).Edge());
  } else if (!params.sharp_te) {
    outline.Add(BRepBuilderAPI_MakeEdge(te_upper, te_lower).Edge());
  }
  outline.Add(BRepBuilderAPI_MakeEdge(lower->VIso(1.0)).Edge());
  if (!outline.IsDone()) throw std::runtime_error("cranked: the tip section's outline does not close");
  ShapeFix_Face tip(BRepBuilderAPI_MakeFace(outline.Wire(), /*OnlyPlane=*/true).Face());
  tip.Perform();
  sewing.Add(tip.Face());
  sewing.Perform();
  return capped(sewing.SewedShape());
}

TopoDS_Shape cranked(const semimesh::mock_cad::NacaWingParams& params, bool split_base = false) {
  return paneled(params, kCrank, 2, split_base);
}

// A piecewise linear map of parameters: old knot values -> new ones (extended linearly past the ends).
struct KnotMap {
  std::vector<double> from, to;
  double operator()(double x) const {
    std::size_t k = 1;
    while (k + 1 < from.size() && x > from[k]) ++k;
    return to[k - 1] + (x - from[k - 1]) * (to[k] - to[k - 1]) / (from[k] - from[k - 1]);
  }
};

// The surface cut into 6 x 6 Bezier patches of parameter lengths cycling 1 : 8 : 3 in each
// direction: with every interior knot at full multiplicity each span is its own polynomial piece,
// so moving the knots reparametrises each piece affinely and leaves the surface as it was.
Handle(Geom_BSplineSurface) bezier_patches(const Geom_BSplineSurface& surface, KnotMap& u_map, KnotMap& v_map) {
  Handle(Geom_BSplineSurface) out = Handle(Geom_BSplineSurface)::DownCast(surface.Copy());
  constexpr double kLengths[] = {1.0, 8.0, 3.0};
  double u0, u1, v0, v1;
  out->Bounds(u0, u1, v0, v1);
  for (int k = 1; k < 6; ++k) {
    out->InsertUKnot(u0 + k * (u1 - u0) / 6, out->UDegree(), 1e-12);
    out->InsertVKnot(v0 + k * (v1 - v0) / 6, out->VDegree(), 1e-12);
  }
  for (int i = 2; i < out->NbUKnots(); ++i) out->IncreaseUMultiplicity(i, out->UDegree());
  for (int i = 2; i < out->NbVKnots(); ++i) out->IncreaseVMultiplicity(i, out->VDegree());
  TColStd_Array1OfReal u(1, out->NbUKnots()), v(1, out->NbVKnots());
  u_map = {}, v_map = {};
  for (int i = 1; i <= u.Length(); ++i) {
    u(i) = i == 1 ? 0.0 : u(i - 1) + kLengths[i % 3];
    u_map.from.push_back(out->UKnot(i)), u_map.to.push_back(u(i));
  }
  for (int i = 1; i <= v.Length(); ++i) {
    v(i) = i == 1 ? 0.0 : v(i - 1) + kLengths[(i + 1) % 3];
    v_map.from.push_back(out->VKnot(i)), v_map.to.push_back(v(i));
  }
  out->SetUKnots(u);
  out->SetVKnots(v);
  return out;
}

// An edge's straight pcurve (an iso-line of the old parameters) seen through the knot maps: a
// polyline of degree 1 with a vertex wherever the line crosses a knot, exact.
Handle(Geom2d_BSplineCurve) mapped_pcurve(const Handle(Geom2d_Curve)& pcurve, double first, double last,
                                          const KnotMap& u_map, const KnotMap& v_map) {
  const gp_Pnt2d a = pcurve->Value(first), b = pcurve->Value(last);
  std::vector<double> at{first, last};
  for (const auto& [map, coordinate] : {std::pair{&u_map, 0}, std::pair{&v_map, 1}})
    for (double knot : map->from) {
      const double ca = coordinate == 0 ? a.X() : a.Y(), cb = coordinate == 0 ? b.X() : b.Y();
      if (std::abs(cb - ca) > 1e-12 && (knot - ca) * (knot - cb) < 0) at.push_back(first + (knot - ca) / (cb - ca) * (last - first));
    }
  std::sort(at.begin(), at.end());
  TColgp_Array1OfPnt2d poles(1, static_cast<int>(at.size()));
  TColStd_Array1OfReal knots(1, static_cast<int>(at.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(at.size()));
  for (std::size_t k = 0; k < at.size(); ++k) {
    const gp_Pnt2d p = pcurve->Value(at[k]);
    poles(static_cast<int>(k) + 1) = gp_Pnt2d(u_map(p.X()), v_map(p.Y()));
    knots(static_cast<int>(k) + 1) = at[k];
    mults(static_cast<int>(k) + 1) = k == 0 || k + 1 == at.size() ? 2 : 1;
  }
  return new Geom2d_BSplineCurve(poles, knots, mults, 1);
}

// The capped body with each B-spline face whose edges are iso-lines given the Bezier-patch copy of
// its surface, and its edges' pcurves mapped to it (the same topology, the same geometry).
TopoDS_Shape with_bezier_patches(const TopoDS_Shape& body) {
  const TopoDS_Shape shape = BRepBuilderAPI_Copy(capped(body)).Shape();
  BRep_Builder builder;
  int rewritten = 0;
  for (const TopoDS_Face& face : faces_of(shape)) {
    TopLoc_Location location;
    const Handle(Geom_BSplineSurface) s =
        Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face, location));
    if (s.IsNull()) continue;
    KnotMap u_map, v_map;
    const Handle(Geom_BSplineSurface) patches = bezier_patches(*s, u_map, v_map);
    std::vector<std::pair<TopoDS_Edge, Handle(Geom2d_BSplineCurve)>> pcurves;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
      double first, last;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (pcurve.IsNull() || !pcurve->IsKind(STANDARD_TYPE(Geom2d_Line)))
        throw std::runtime_error("bezier_patches: a pcurve that is not an iso-line");
      pcurves.emplace_back(edge, mapped_pcurve(pcurve, first, last, u_map, v_map));
    }
    builder.UpdateFace(face, patches, location, BRep_Tool::Tolerance(face));
    for (const auto& [edge, pcurve] : pcurves) builder.UpdateEdge(edge, pcurve, face, BRep_Tool::Tolerance(edge));
    ++rewritten;
  }
  if (rewritten == 0) throw std::runtime_error("bezier_patches: no B-spline face");
  return shape;
}

// The pinched_tip wing's skin: NACA 0012 half-sections up the span (z), each scaled in thickness by
// 1 up to 0.75 span, then by an ellipse's quarter to 0 at the tip (the chord line); an upper and a
// lower face, each lofted through its half-sections (trailing edge to leading edge), sewn along both
// edges (a sharp trailing edge).
TopoDS_Shape pinched_tip(double chord) {
  const int sections = 17, points_per_section = 41;
  BRepBuilderAPI_Sewing sewing(1e-6 * chord);
  for (const double side : {1.0, -1.0}) {
    BRepOffsetAPI_ThruSections loft(/*isSolid=*/false, /*ruled=*/false, 1e-7 * chord);
    for (int i = 0; i < sections; ++i) {
      const double s = i / (sections - 1.0);
      const double z = 1.0 - (1.0 - s) * (1.0 - s);  // sections closer towards the tip
      const double e = z <= 0.75 ? 0.0 : (z - 0.75) / 0.25;
      const double thickness = std::sqrt(std::max(0.0, 1.0 - e * e));
      Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, points_per_section);
      for (int j = 1; j <= points_per_section; ++j) {
        const double x = 0.5 * (1.0 + std::cos(M_PI * (j - 1.0) / (points_per_section - 1.0)));  // 1 -> 0
        const double half = 5.0 * 0.12 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                                          0.1036 * x * x * x * x);
        points->SetValue(j, gp_Pnt(chord * x, side * chord * thickness * half, chord * z));
      }
      GeomAPI_Interpolate curve(points, /*periodic=*/false, 1e-9 * chord);
      curve.Perform();
      loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve.Curve()).Edge()).Wire());
    }
    loft.CheckCompatibility(false);
    loft.Build();
    if (!loft.IsDone()) throw std::runtime_error("pinched_tip: the loft failed");
    for (TopExp_Explorer f(loft.Shape(), TopAbs_FACE); f.More(); f.Next()) sewing.Add(f.Current());
  }
  sewing.Perform();
  return sewing.SewedShape();
}

// The seam_skin wing's skin: closed NACA 0012 sections (trailing edge, upper side, leading edge,
// lower side, trailing edge) lofted from z = 0 to 1 into one face closed round the section, its seam
// the sharp trailing edge; root and tip left open.
TopoDS_Shape seam_skin(double chord) {
  const int sections = 5, half = 41;
  BRepOffsetAPI_ThruSections loft(/*isSolid=*/false, /*ruled=*/false, 1e-7 * chord);
  for (int i = 0; i < sections; ++i) {
    const double z = i / (sections - 1.0);
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 2 * half - 1);
    for (int j = 1; j <= 2 * half - 1; ++j) {
      const double a = M_PI * (j - 1.0) / (half - 1.0);  // 0 .. 2 pi: over the upper side and back under
      const double x = 0.5 * (1.0 + std::cos(a));
      const double t = 5.0 * 0.12 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                                     0.1036 * x * x * x * x);
      points->SetValue(j, gp_Pnt(chord * x, (j < half ? 1.0 : -1.0) * chord * t, chord * z));
    }
    GeomAPI_Interpolate curve(points, /*periodic=*/false, 1e-9 * chord);
    curve.Perform();
    loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve.Curve()).Edge()).Wire());
  }
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("seam_skin: the loft failed");
  return loft.Shape();
}

TopoDS_Shape variant(const std::string& name, const TopoDS_Shape& wing, const semimesh::mock_cad::NacaWingParams& params) {
  if (name == "asis") return wing;
  if (name == "nurbs") return BRepBuilderAPI_NurbsConvert(wing, /*Copy=*/true).Shape();
  if (name == "capped") return capped(wing);
  if (name == "open_tip") return without_tip(wing, params);
  if (name == "unsewn") return unsewn(wing, params.chord);
  if (name == "hemisphere") return in_hemisphere(wing, params.chord);
  if (name == "two_bodies") return compound_of({wing, moved(wing, gp_Vec(0, 3 * params.chord, 0))});
  if (name == "no_body") return BRepPrimAPI_MakeBox(gp_Pnt(-1, -1, 0), gp_Pnt(2, 1, 1)).Shape();
  if (name == "fuselage") return on_fuselage(wing, params.chord, Fuselage::Cylinder);
  if (name == "fuselage_bspline") return on_fuselage(wing, params.chord, Fuselage::BSpline);
  if (name == "fuselage_dihedral") return on_fuselage(wing, params.chord, Fuselage::Dihedral);
  if (name == "fuselage_seam_on_crest") return on_fuselage(wing, params.chord, Fuselage::SeamOnCrest);
  if (name == "fuselage_unjoined")
    return compound_of({sunk_wing(wing, params.chord, Fuselage::Cylinder), fuselage_solid(Fuselage::Cylinder, params.chord)});
  if (name == "fuselage_bspline_unjoined")
    return compound_of({sunk_wing(wing, params.chord, Fuselage::BSpline),
                        fuselage_solid(Fuselage::BSpline, params.chord, /*spline_seam_on_crest=*/true)});
  if (name == "fuselage_nosed_unjoined")
    return compound_of({sunk_wing(wing, params.chord, Fuselage::BSpline),
                        fuselage_solid(Fuselage::Nosed, params.chord, /*spline_seam_on_crest=*/true)});
  if (name == "fuselage_unjoined_fin") {
    const TopoDS_Shape sunk = sunk_wing(wing, params.chord, Fuselage::Cylinder);
    gp_Trsf half_turn;
    half_turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, -1.5 * params.chord), gp::DX()), M_PI);
    return compound_of({sunk, BRepBuilderAPI_Transform(sunk, half_turn, /*copy=*/true).Shape(),
                        fuselage_solid(Fuselage::Cylinder, params.chord)});
  }
  if (name == "fuselage_through") {  // one wing through the fuselage, both halves one solid
    // Each half 1.6 chords longer, sunk 1.6 chords: past the axis, where the two halves overlap.
    semimesh::mock_cad::NacaWingParams longer = params;
    longer.span += 1.6 * params.chord;
    const TopoDS_Shape sunk =
        sunk_wing(semimesh::occ::make_naca_wing_shape(longer), params.chord, Fuselage::Cylinder, 1.6);
    gp_Trsf half_turn;
    half_turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, -1.5 * params.chord), gp::DX()), M_PI);
    BRepAlgoAPI_Fuse span(sunk, BRepBuilderAPI_Transform(sunk, half_turn, /*copy=*/true).Shape());
    if (!span.IsDone()) throw std::runtime_error("fuselage_through: the Boolean fuse of the two halves failed");
    return compound_of({span.Shape(), fuselage_solid(Fuselage::Cylinder, params.chord)});
  }
  if (name == "cranked") return cranked(params);
  if (name == "cranked_split_base") return cranked(params, /*split_base=*/true);
  if (name == "split_base") return paneled(params, kStraight, 1, /*split_base=*/true);
  if (name == "bezier_patches") return with_bezier_patches(wing);
  if (name == "pinched_tip") return pinched_tip(params.chord);
  if (name == "seam_skin") return seam_skin(params.chord);
  throw std::invalid_argument("unknown variant '" + name +
                              "' (known: asis, nurbs, capped, open_tip, unsewn, hemisphere, two_bodies, no_body, "
                              "fuselage, fuselage_bspline, fuselage_dihedral, fuselage_seam_on_crest, fuselage_unjoined, fuselage_unjoined_fin, fuselage_bspline_unjoined, fuselage_nosed_unjoined, fuselage_through, cranked, cranked_mm, "
                              "cranked_m, split_base, cranked_split_base, bezier_patches, pinched_tip, seam_skin)");
}

// IGES trimmed faces (mode 0: each face on its own, as CAD tools export surfaces) under the unit
// flag INCH, the numbers being the shape's own (OCC writes in its session unit, millimetres:
// scaled by 25.4 first, the file's numbers are the chord's).
void write_iges_inch_flag(const TopoDS_Shape& shape, const char* path) {
  IGESControl_Controller::Init();
  gp_Trsf scale;
  scale.SetScale(gp::Origin(), 25.4);
  IGESControl_Writer writer("IN", 0);
  if (!writer.AddShape(BRepBuilderAPI_Transform(shape, scale, /*copy=*/true).Shape()) ||
      (writer.ComputeModel(), !writer.Write(path)))
    throw std::runtime_error(std::string("cannot write '") + path + "'");
}

// The cranked wing at a root chord of 1 m, in OCC's session unit (millimetres): the writer
// converts it to the file's unit.
TopoDS_Shape cranked_in_mm(semimesh::mock_cad::NacaWingParams params) {
  params.chord = 1000;
  return cranked(params);
}

// STEP in the given unit ("MM", "M"): the numbers are the shape's (millimetres) converted to it.
void write_step_in(const TopoDS_Shape& shape, const char* unit, const char* path) {
  STEPControl_Controller::Init();  // the static below exists once the STEP controller is
  Interface_Static::SetCVal("write.step.unit", unit);
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path) != IFSelect_RetDone)
    throw std::runtime_error(std::string("cannot write '") + path + "'");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: write_wing_variant VARIANT OUT.step [naca.key=value ...]\n";
    return 1;
  }
  try {
    semimesh::cad::Params params;
    for (int i = 3; i < argc; ++i) {
      const std::string kv = argv[i];
      const auto eq = kv.find('=');
      if (eq == std::string::npos || kv.rfind("naca.", 0) != 0) throw std::invalid_argument("expected naca.key=value, got '" + kv + "'");
      params.set(kv.substr(0, eq), kv.substr(eq + 1));
    }
    const semimesh::mock_cad::NacaWingParams wing = semimesh::mock_cad::naca_params_from(params);
    const std::string name = argv[1];
    if (name == "cranked_mm" || name == "cranked_m") {
      write_step_in(cranked_in_mm(wing), name == "cranked_mm" ? "MM" : "M", argv[2]);
      return 0;
    }
    const TopoDS_Shape shape = variant(name, semimesh::occ::make_naca_wing_shape(wing), wing);
    if (name == "unsewn") {
      write_iges_inch_flag(shape, argv[2]);
      return 0;
    }
    STEPControl_Writer writer;
    if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(argv[2]) != IFSelect_RetDone)
      throw std::runtime_error(std::string("cannot write '") + argv[2] + "'");
    return 0;
  } catch (const Standard_Failure& e) {
    std::cerr << "write_wing_variant: OCC: " << e.GetMessageString() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "write_wing_variant: " << e.what() << "\n";
  }
  return 1;
}
