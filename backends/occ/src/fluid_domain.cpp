#include "fluid_domain.hpp"

#include "body_cut.hpp"
#include "closed_face_halves.hpp"
#include "crease_seam.hpp"
#include "domain_by_sides.hpp"
#include "joined_patches.hpp"
#include "parameter_rectangle.hpp"
#include "seam_away.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_FindPlane.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <GProp_PEquation.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <optional>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <BRepLib.hxx>
#include <Geom_Plane.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Wire.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Ax3.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace semimesh::occ {
namespace {

using cad::CadError;

[[noreturn]] void refuse(const std::string& what) { throw CadError(CadError::Kind::BadParameter, what); }

std::string length_text(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

// The largest tolerance of `shape`'s edges: a section a cut leaves lies in its plane that closely
// (OCCT's intersection curves carry the approximation's error as their tolerance).
double edge_tolerance(const TopoDS_Shape& shape) {
  double largest = 0.0;
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next())
    largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
  return largest;
}

// The plane `loop`'s points lie in (32 along each edge), within `tolerance`: a section a cut left
// along a B-spline surface's iso-line lies in its plane though its curve's poles do not, which is
// what OCCT's plane finders test.
std::optional<gp_Pln> plane_through_points(const TopoDS_Shape& loop, double tolerance) {
  std::vector<gp_Pnt> samples;
  for (TopExp_Explorer e(loop, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    for (int k = 0; k < 32; ++k)
      samples.push_back(curve.Value(curve.FirstParameter() + k / 32.0 * (curve.LastParameter() - curve.FirstParameter())));
  }
  TColgp_Array1OfPnt points(1, static_cast<int>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i) points(static_cast<int>(i) + 1) = samples[i];
  const GProp_PEquation fit(points, tolerance);
  if (!fit.IsPlanar()) return std::nullopt;
  return fit.Plane();
}

// A planar cap whose area is below the tolerance times its size: its loop runs out and back along
// itself (a section pinched to zero thickness).
bool encloses_no_area(const TopoDS_Face& cap, const TopoDS_Shape& loop, double tolerance) {
  Bnd_Box b;
  BRepBndLib::Add(loop, b);
  return std::abs(surface_area(cap)) <= tolerance * std::sqrt(b.SquareExtent());
}

// The free loops of a shell (edges that bound one of its faces only), each closed by a planar face
// through it, sewn on: an open root (the root section as free curves in the wall plane) or an open
// flat tip becomes a closed body. A free loop that is not closed or not planar, or that encloses no
// area (a section pinched to zero thickness, its loop running out and back along itself), is
// refused by place. `what` names the key and the part: "geometry.wall_plane: the body".
TopoDS_Shape with_planar_loops_capped(const TopoDS_Shell& shell, double tolerance, const std::string& what,
                                      std::vector<std::string>& repairs) {
  ShapeAnalysis_FreeBounds bounds(shell, tolerance, /*splitclosed=*/false, /*splitopen=*/true);
  const TopoDS_Compound& closed = bounds.GetClosedWires();
  const TopoDS_Compound& open = bounds.GetOpenWires();
  if (TopExp_Explorer(open, TopAbs_EDGE).More()) {
    Bnd_Box b;
    BRepBndLib::Add(open, b);
    const gp_Pnt c = b.CornerMin().XYZ() * 0.5 + b.CornerMax().XYZ() * 0.5;
    refuse(what + "'s free edges near (" + length_text(c.X()) + ", " + length_text(c.Y()) + ", " +
           length_text(c.Z()) + ") form no closed loop, so no face can close the body there (sew it with "
           "geometry.sew_tolerance, or close it in a CAD tool)");
  }
  if (!TopExp_Explorer(closed, TopAbs_WIRE).More()) return shell;
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(shell);
  for (TopExp_Explorer w(closed, TopAbs_WIRE); w.More(); w.Next()) {
    const TopoDS_Wire& wire = TopoDS::Wire(w.Current());
    // Exactly planar, or planar within the tolerance the faces were sewn at (an export with gaps).
    BRepBuilderAPI_MakeFace cap(wire, /*OnlyPlane=*/true);
    if (!cap.IsDone())
      if (BRepBuilderAPI_FindPlane plane(wire, std::max(tolerance, edge_tolerance(wire))); plane.Found())
        cap = BRepBuilderAPI_MakeFace(plane.Plane()->Pln(), wire);
    if (!cap.IsDone())
      if (const std::optional<gp_Pln> plane = plane_through_points(wire, std::max(tolerance, edge_tolerance(wire))))
        cap = BRepBuilderAPI_MakeFace(*plane, wire);
    if (!cap.IsDone()) {
      Bnd_Box b;
      BRepBndLib::Add(w.Current(), b);
      const gp_Pnt c = b.CornerMin().XYZ() * 0.5 + b.CornerMax().XYZ() * 0.5;
      refuse(what + " is open along a loop of free edges around (" + length_text(c.X()) + ", " +
             length_text(c.Y()) + ", " + length_text(c.Z()) + ") that does not lie in one plane; only a planar "
             "opening (an open root or flat tip) is closed here: close it in a CAD tool");
    }
    Bnd_Box b;
    BRepBndLib::Add(wire, b);
    const gp_Pnt c = b.CornerMin().XYZ() * 0.5 + b.CornerMax().XYZ() * 0.5;
    if (encloses_no_area(cap.Face(), wire, tolerance))
      refuse(what + " is open along a loop of free edges around (" + length_text(c.X()) + ", " + length_text(c.Y()) +
             ", " + length_text(c.Z()) + ") that encloses no area (a section pinched to zero thickness, as a "
             "knife-edge or pointed tip): no face can close it. Cut the body where it has thickness, "
             "geometry.body_cut = {point = [...], normal = [...]} (the part its normal points to taken away), or "
             "close the part in a CAD tool");
    sewing.Add(cap.Face());
    int edges = 0;
    for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ++edges;
    repairs.push_back("closed an open flat loop of " + std::to_string(edges) + " free edge(s) around (" +
                      length_text(c.X()) + ", " + length_text(c.Y()) + ", " + length_text(c.Z()) + ") with a planar face");
  }
  sewing.Perform();
  return sewing.SewedShape();
}

// The body as solids with their normals pointing out of them: its solids, else its shells (open
// ones closed across their planar openings) made solid. `what` as for with_planar_loops_capped.
TopoDS_Shape body_solids(const TopoDS_Shape& body, double tolerance, const std::string& what,
                         std::vector<std::string>& repairs) {
  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  int count = 0;
  for (TopExp_Explorer s(body, TopAbs_SOLID); s.More(); s.Next(), ++count) builder.Add(solids, s.Current());
  // Shells, and the faces in none (a body of one face: sewing a lone face leaves it a face) as one.
  std::vector<TopoDS_Shell> shells;
  for (TopExp_Explorer s(body, TopAbs_SHELL, TopAbs_SOLID); s.More(); s.Next()) shells.push_back(TopoDS::Shell(s.Current()));
  if (TopExp_Explorer loose(body, TopAbs_FACE, TopAbs_SHELL); loose.More()) {
    shells.emplace_back();
    builder.MakeShell(shells.back());
    for (; loose.More(); loose.Next()) builder.Add(shells.back(), loose.Current());
  }
  for (const TopoDS_Shell& shell : shells) {
    const TopoDS_Shape closed = with_planar_loops_capped(shell, tolerance, what, repairs);
    for (TopExp_Explorer sh(closed, TopAbs_SHELL); sh.More(); sh.Next(), ++count) {
      BRepBuilderAPI_MakeSolid make(TopoDS::Shell(sh.Current()));
      if (!make.IsDone()) refuse(what + "'s shell cannot be made a solid (is it closed?)");
      TopoDS_Solid solid = make.Solid();
      BRepLib::OrientClosedSolid(solid);
      builder.Add(solids, solid);
    }
  }
  if (count == 0) refuse(what + ": no closed part (no solid, no shell) in the CAD file");
  return solids;
}

gp_Pnt centre_of(const TopoDS_Shape& shape) {
  Bnd_Box b;
  BRepBndLib::Add(shape, b);
  return b.CornerMin().XYZ() * 0.5 + b.CornerMax().XYZ() * 0.5;
}

// Whether the edges of `shape` lie inside the solid `wall`, clear of its boundary by more than
// `tolerance`, at 32 points along each (a point's distance to the wall: OCCT's curve-to-curve
// distances to a fuselage's degenerate pole edges take minutes).
bool clear_inside(const TopoDS_Shape& shape, const TopoDS_Shape& wall, double tolerance) {
  BRepClass3d_SolidClassifier where(wall);
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    for (int k = 0; k <= 32; ++k) {
      const gp_Pnt p = curve.Value(curve.FirstParameter() + k / 32.0 * (curve.LastParameter() - curve.FirstParameter()));
      where.Perform(p, tolerance);
      if (where.State() != TopAbs_IN) return false;
      BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(p).Vertex(), wall);
      if (!distance.IsDone() || distance.Value() <= tolerance) return false;
    }
  }
  return true;
}

// The least distance from the edges of `shape` to `wall`, at 32 points along each (as clear_inside).
double distance_to(const TopoDS_Shape& shape, const TopoDS_Shape& wall) {
  double least = std::numeric_limits<double>::infinity();
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    for (int k = 0; k <= 32; ++k) {
      const gp_Pnt p = curve.Value(curve.FirstParameter() + k / 32.0 * (curve.LastParameter() - curve.FirstParameter()));
      BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(p).Vertex(), wall);
      if (distance.IsDone()) least = std::min(least, distance.Value());
    }
  }
  return least;
}

// The closed free loops of `shell` (its open ones are refused when it is capped).
std::vector<TopoDS_Wire> free_loops(const TopoDS_Shape& shell, double tolerance) {
  std::vector<TopoDS_Wire> loops;
  for (TopExp_Explorer s(shell, TopAbs_SHELL); s.More(); s.Next()) {
    ShapeAnalysis_FreeBounds bounds(s.Current(), tolerance, /*splitclosed=*/false, /*splitopen=*/true);
    for (TopExp_Explorer w(bounds.GetClosedWires(), TopAbs_WIRE); w.More(); w.Next()) loops.push_back(TopoDS::Wire(w.Current()));
  }
  return loops;
}

// A join's body with each free loop pinched to zero thickness that lies inside the wall part (an
// OpenVSP wing's centreline section, flattened to a line inside the fuselage) trimmed back by a plane
// parallel to the loop's, halfway to the wall part's surface (closer when the section there is not
// clear inside the wall): what is cut away lies inside the wall part, which the join takes away
// anyway, and the new section encloses area, so it is capped as any open root. Other loops are left
// for the capping to close or refuse.
TopoDS_Shape with_pinched_loops_inside_trimmed(TopoDS_Shape body, const TopoDS_Shape& wall, double tolerance,
                                               FaceNames& names, std::vector<std::string>& repairs) {
  bool trimmed = true;
  for (int round = 0; trimmed && round < 8; ++round) {
    trimmed = false;
    for (const TopoDS_Wire& loop : free_loops(body, tolerance)) {
      const BRepBuilderAPI_FindPlane fit(loop, tolerance);
      if (!fit.Found()) continue;
      const BRepBuilderAPI_MakeFace cap(fit.Plane()->Pln(), loop);
      if (!cap.IsDone() || !encloses_no_area(cap.Face(), loop, tolerance) || !clear_inside(loop, wall, tolerance)) continue;
      const gp_Pnt c = centre_of(loop);
      gp_Dir into_body = fit.Plane()->Pln().Axis().Direction();
      if (gp_Vec(c, centre_of(body)).Dot(gp_Vec(into_body)) < 0.0) into_body.Reverse();
      for (double depth = 0.5 * distance_to(loop, wall); depth > 10.0 * tolerance && !trimmed; depth *= 0.5) {
        const CutPlane cut{c.Translated(depth * gp_Vec(into_body)), into_body.Reversed(), "the body's pinched loop"};
        FaceNames carried = names;
        const TopoDS_Shape left = cut_beyond(body, cut, 0.1 * tolerance, carried);
        const std::vector<TopoDS_Wire> sections = free_loops(left, tolerance);
        const bool section_inside = std::all_of(sections.begin(), sections.end(), [&](const TopoDS_Wire& w) {
          return std::abs(gp_Vec(cut.point, centre_of(w)).Dot(gp_Vec(cut.normal))) > 10.0 * tolerance ||
                 clear_inside(w, wall, tolerance);
        });
        if (!section_inside) continue;
        body = left;
        names = std::move(carried);
        repairs.push_back("trimmed the body's free loop pinched to zero thickness around (" + length_text(c.X()) + ", " +
                          length_text(c.Y()) + ", " + length_text(c.Z()) + ") back by " + length_text(depth) +
                          " inside the wall part (what the join takes away)");
        trimmed = true;
      }
      if (trimmed) break;
    }
  }
  return body;
}

// The body cut where the user says (geometry.body_cut), said in `repairs`.
TopoDS_Shape cut_body(const TopoDS_Shape& body, const CutPlane& cut, double tolerance, FaceNames& names,
                      std::vector<std::string>& repairs) {
  const TopoDS_Shape left = cut_beyond(body, cut, 0.1 * tolerance, names);
  repairs.push_back("cut the body at " + cut.label + ": its part beyond taken away, the opening closed flat");
  return left;
}

// Bounding box of `shape` in the wall's frame (the plane is z = 0, z along the fluid normal).
Bnd_Box box_in_wall_frame(const TopoDS_Shape& shape, const WallPlane& wall) {
  gp_Trsf to_wall;
  to_wall.SetTransformation(gp_Ax3(wall.point, wall.normal));
  Bnd_Box box;
  BRepBndLib::AddOptimal(BRepBuilderAPI_Transform(shape, to_wall, /*copy=*/true).Shape(), box, false, false);
  return box;
}

double height_min(const Bnd_Box& b) {
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  return z0;
}

double height_max(const Bnd_Box& b) {
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  return z1;
}

// Whatever its surface type (a planar B-spline cap counts): all of it within tolerance of the plane.
bool lies_in_plane(const TopoDS_Face& face, const WallPlane& wall, double tolerance) {
  const Bnd_Box b = box_in_wall_frame(face, wall);
  return std::abs(height_min(b)) <= tolerance && std::abs(height_max(b)) <= tolerance;
}

// The body's faces in the plane (its root); refuses a body that does not stand on the plane.
std::vector<TopoDS_Face> root_faces(const TopoDS_Shape& body, const WallPlane& wall, double tolerance) {
  const Bnd_Box extent = box_in_wall_frame(body, wall);
  const double lowest = height_min(extent);
  if (height_max(extent) <= tolerance)
    refuse(wall.label + ": the body lies on the side the normal points away from: the normal must point into "
           "the fluid, to the body's side");
  if (lowest < -tolerance)
    refuse(wall.label + ": the plane cuts through the body: the body reaches " + length_text(-lowest) +
           " below it (the root must lie in the plane, the body on the side its normal points to)");
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer f(body, TopAbs_FACE); f.More(); f.Next())
    if (lies_in_plane(TopoDS::Face(f.Current()), wall, tolerance)) faces.push_back(TopoDS::Face(f.Current()));
  if (faces.empty())
    refuse(wall.label + ": the body does not touch the plane: no face of it lies in the plane (its nearest point is " +
           length_text(lowest) + " above it)");
  return faces;
}

Bnd_Box global_box(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  return box;
}

// The far field as a solid.
TopoDS_Shape far_solid(const FarFieldShape& far, const gp_Dir& normal, const TopoDS_Shape& body,
                       const std::vector<TopoDS_Face>& roots) {
  if (far.box) {
    const auto& b = *far.box;
    return BRepPrimAPI_MakeBox(gp_Pnt(b[0], b[1], b[2]), gp_Pnt(b[3], b[4], b[5])).Solid();
  }
  if (far.sphere) {
    // Its axis along the wall's normal: a wall through the centre cuts it along its equator (an
    // iso-parameter line), the pole at the top.
    const auto& s = *far.sphere;
    return BRepPrimAPI_MakeSphere(gp_Ax2(gp_Pnt(s[0], s[1], s[2]), normal), s[3]).Solid();
  }
  // The root chord: the largest extent of the root's bounding box.
  Bnd_Box root;
  for (const TopoDS_Face& f : roots) BRepBndLib::AddOptimal(f, root, false, false);
  double r0, r1, r2, r3, r4, r5;
  root.Get(r0, r1, r2, r3, r4, r5);
  const double margin = *far.box_chords * std::max({r3 - r0, r4 - r1, r5 - r2});
  double b0, b1, b2, b3, b4, b5;
  global_box(body).Get(b0, b1, b2, b3, b4, b5);
  return BRepPrimAPI_MakeBox(gp_Pnt(b0 - margin, b1 - margin, b2 - margin), gp_Pnt(b3 + margin, b4 + margin, b5 + margin))
      .Solid();
}

// Each solid of `body` inside the far field, none crossing or touching its boundary. With
// `others_outside` (the pieces of a joined body standing out of its wall part: a full-span wing
// through a fuselage stands out twice, and a half model's box keeps one) a piece may lie wholly
// outside instead, one at least inside.
void require_inside(const TopoDS_Shape& body, const TopoDS_Shape& far_field, const FarFieldShape& far, double tolerance,
                    bool others_outside = false) {
  TopExp_Explorer shell(far_field, TopAbs_SHELL);
  int inside = 0, outside = 0;
  for (TopExp_Explorer solid(body, TopAbs_SOLID); solid.More(); solid.Next()) {
    BRepExtrema_DistShapeShape distance(solid.Current(), shell.Current());
    if (!distance.IsDone()) refuse(far.label + ": the distance from the body to the far field cannot be computed");
    if (distance.Value() <= tolerance) {
      const gp_Pnt p = distance.PointOnShape1(1);
      refuse(far.label + ": the far field does not contain the body: its boundary crosses or touches the body at (" +
             length_text(p.X()) + ", " + length_text(p.Y()) + ", " + length_text(p.Z()) + ")");
    }
    TopExp_Explorer vertex(solid.Current(), TopAbs_VERTEX);
    BRepClass3d_SolidClassifier where(far_field, BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())), tolerance);
    ++(where.State() == TopAbs_IN ? inside : outside);
  }
  if (inside == 0 || (outside > 0 && !others_outside))
    refuse(far.label + ": the far field does not contain the body: the body lies outside it");
}

// Each solid of `domain`: its volume and bounding box, for a message.
std::string pieces_text(const TopoDS_Shape& domain) {
  std::string text;
  int k = 0;
  for (TopExp_Explorer solid(domain, TopAbs_SOLID); solid.More(); solid.Next()) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(solid.Current(), props);
    const Bnd_Box b = global_box(solid.Current());
    text += (k++ ? "; " : "") + std::string("volume ") + length_text(std::abs(props.Mass())) + " within (" +
            length_text(b.CornerMin().X()) + ", " + length_text(b.CornerMin().Y()) + ", " + length_text(b.CornerMin().Z()) +
            ") .. (" + length_text(b.CornerMax().X()) + ", " + length_text(b.CornerMax().Y()) + ", " +
            length_text(b.CornerMax().Z()) + ")";
  }
  return text;
}

// A box standing on the wall plane on its fluid side, larger than everything else: the half space.
TopoDS_Shape fluid_half_space(const WallPlane& wall, const TopoDS_Shape& far_field) {
  const Bnd_Box b = global_box(far_field);
  const double size = 4.0 * (std::sqrt(b.SquareExtent()) + gp_Pnt(0, 0, 0).Distance(wall.point) + 1.0);
  const gp_Ax3 frame(wall.point, wall.normal);
  const gp_Pnt corner = wall.point.Translated(-size * gp_Vec(frame.XDirection()) - size * gp_Vec(frame.YDirection()));
  return BRepPrimAPI_MakeBox(gp_Ax2(corner, wall.normal, frame.XDirection()), 2 * size, 2 * size, size).Solid();
}

// `fuzzy`: the distance below which the operation takes entities as coincident (OCCT's fuzzy
// Booleans): a root sewn across gaps lies in the wall plane only that closely.
template <class Operation>
TopoDS_Shape run(Operation& op, const TopoDS_Shape& object, const TopoDS_Shape& tool, double fuzzy, const std::string& what) {
  op.SetFuzzyValue(fuzzy);
  TopTools_ListOfShape objects, tools;
  objects.Append(object);
  tools.Append(tool);
  op.SetArguments(objects);
  op.SetTools(tools);
  op.Build();
  if (!op.IsDone() || op.HasErrors()) {
    std::ostringstream report;
    op.DumpErrors(report);
    refuse("geometry.wall_plane | geometry.join / geometry.farfield: OCCT's Boolean operation (" + what + ") failed: " +
           report.str());
  }
  return op.Shape();
}

// The faces of the result that come from `face` through the operation (itself when left as it was).
TopTools_ListOfShape images(BRepAlgoAPI_BooleanOperation& op, const TopoDS_Shape& face) {
  TopTools_ListOfShape out = op.Modified(face);
  if (out.IsEmpty() && !op.IsDeleted(face)) out.Append(face);
  return out;
}

// Names of the result's faces: the body's as carried through the cut (unnamed body faces stay
// unnamed), "wall" on the plane, the rest far field.
FaceNames domain_names(const TopoDS_Shape& domain, BRepAlgoAPI_Cut& cut, const TopoDS_Shape& body,
                       const FaceNames& body_names, const WallPlane& wall, double tolerance) {
  FaceNames names;
  for (const auto& [face, name] : body_names)
    for (const TopoDS_Shape& image : images(cut, face)) names.emplace_back(image, name);
  TopTools_ListOfShape from_body;
  for (TopExp_Explorer f(body, TopAbs_FACE); f.More(); f.Next()) {
    TopTools_ListOfShape of_face = images(cut, f.Current());
    from_body.Append(of_face);
  }
  int walls = 0, outer = 0;
  for (TopExp_Explorer f(domain, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    if (std::any_of(from_body.begin(), from_body.end(), [&](const TopoDS_Shape& b) { return b.IsSame(face); })) continue;
    if (lies_in_plane(face, wall, tolerance))
      names.emplace_back(face, walls++ ? "wall_" + std::to_string(walls) : std::string("wall"));
    else
      names.emplace_back(face, "farfield_" + std::to_string(outer++));
  }
  return names;
}

// The faces of `shape` an entry names, numbered as the model numbers them (model_from_shape:
// TopExp::MapShapes): "#<id>", "face_<id>", or a name the file gives (every face of that name).
std::vector<TopoDS_Face> named_faces(const TopTools_IndexedMapOfShape& faces, const FaceNames& names,
                                     const std::string& entry, const std::string& key) {
  std::vector<TopoDS_Face> out;
  const std::string id_text = entry.rfind('#', 0) == 0 ? entry.substr(1)
                              : entry.rfind("face_", 0) == 0 ? entry.substr(5)
                                                             : std::string();
  if (!id_text.empty() && id_text.find_first_not_of("0123456789") == std::string::npos) {
    const int id = std::stoi(id_text);
    if (id >= faces.Extent())
      refuse(key + ": no face " + entry + ": the file has " + std::to_string(faces.Extent()) + " faces, #0 .. #" +
             std::to_string(faces.Extent() - 1) + " (semimesh cad-info FILE lists them)");
    out.push_back(TopoDS::Face(faces(id + 1)));
    return out;
  }
  for (int i = 1; i <= faces.Extent(); ++i)
    for (const auto& [face, name] : names)
      if (name == entry && face.IsSame(faces(i))) {
        out.push_back(TopoDS::Face(faces(i)));
        break;
      }
  if (out.empty()) refuse(key + ": no face named '" + entry + "' in the file (semimesh cad-info FILE lists them)");
  return out;
}

// The faces a part's entries name, as one shell (they were sewn at load: neighbours share edges).
TopoDS_Shell part_shell(const TopTools_IndexedMapOfShape& faces, const FaceNames& names,
                        const std::vector<std::string>& entries, const std::string& key,
                        TopTools_IndexedMapOfShape& taken) {
  if (entries.empty()) refuse(key + ": no faces given");
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (const std::string& entry : entries)
    for (const TopoDS_Face& face : named_faces(faces, names, entry, key)) {
      if (taken.Contains(face)) refuse(key + ": face " + entry + " is named twice (in geometry.join.body and .wall, or twice)");
      taken.Add(face);
      builder.Add(shell, face);
    }
  return shell;
}

// The faces of `shape` in one shell: its own when it is one (sewing one face returns the face).
TopoDS_Shell one_shell(const TopoDS_Shape& shape) {
  if (TopExp_Explorer shell(shape, TopAbs_SHELL); shell.More()) return TopoDS::Shell(shell.Current());
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) builder.Add(shell, f.Current());
  return shell;
}

// Names of the joined domain's faces: the body's as carried through the split (unnamed body faces
// stay unnamed), "wall" for what is left of the wall part, the rest far field.
FaceNames joined_names(const TopoDS_Shape& fluid, const DomainBySides& domain, const FaceNames& file_names) {
  FaceNames names;
  for (const auto& [face, name] : file_names)
    for (const TopoDS_Shape& piece : domain.pieces(face))
      if (domain.from_body.Contains(piece)) names.emplace_back(piece, name);
  int walls = 0, outer = 0;
  for (TopExp_Explorer f(fluid, TopAbs_FACE); f.More(); f.Next()) {
    if (domain.from_body.Contains(f.Current())) continue;
    if (domain.from_wall.Contains(f.Current()))
      names.emplace_back(f.Current(), walls++ ? "wall_" + std::to_string(walls) : std::string("wall"));
    else
      names.emplace_back(f.Current(), "farfield_" + std::to_string(outer++));
  }
  return names;
}

}  // namespace

TopoDS_Shape fluid_domain(const TopoDS_Shape& body, const WallPlane& wall, const FarFieldShape& far,
                          const std::optional<CutPlane>& body_cut, double tolerance, FaceNames& names,
                          std::vector<std::string>& repairs) {
  const TopoDS_Shape whole = with_crease_seams_split(body, tolerance, names, repairs);
  const TopoDS_Shape solids = body_solids(body_cut ? cut_body(whole, *body_cut, tolerance, names, repairs) : whole,
                                          tolerance, "geometry.wall_plane: the body", repairs);
  const std::vector<TopoDS_Face> roots = root_faces(solids, wall, tolerance);
  const TopoDS_Shape outer = far_solid(far, wall.normal, solids, roots);
  require_inside(solids, outer, far, tolerance);

  BRepAlgoAPI_Common common;
  // The model's tolerance is a tenth of `tolerance` (load_occ.cpp: the sewing tolerance).
  const double fuzzy = 0.1 * tolerance;
  const TopoDS_Shape clipped = run(common, outer, fluid_half_space(wall, outer), fuzzy, "far field on the wall's fluid side");
  BRepAlgoAPI_Cut cut;
  const TopoDS_Shape domain = run(cut, clipped, solids, fuzzy, "far field minus body");
  TopExp_Explorer solid(domain, TopAbs_SOLID);
  if (!solid.More()) refuse(wall.label + ": the Boolean operations left no fluid domain");
  const TopoDS_Shape fluid = solid.Current();
  solid.Next();
  if (solid.More()) refuse(wall.label + ": the fluid domain falls apart into several pieces: " + pieces_text(domain));
  names = domain_names(fluid, cut, solids, names, wall, tolerance);
  return fluid;
}

}  // namespace semimesh::occ

namespace semimesh::occ {

TopoDS_Shape fluid_domain_of_parts(const TopoDS_Shape& shape, const PartsToJoin& parts, const FarFieldShape& far,
                                   const std::optional<CutPlane>& body_cut, double tolerance, FaceNames& names,
                                   std::vector<std::string>& repairs) {
  if (far.box_chords)
    refuse(far.label + ": geometry.join needs the far field as a box or a sphere (box_chords measures a root the "
                       "parts do not have before they are joined)");
  TopTools_IndexedMapOfShape faces, taken;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  const TopoDS_Shell body_faces = part_shell(faces, names, parts.body, "geometry.join.body", taken);
  const TopoDS_Shell wall_faces =
      one_shell(with_patches_joined(part_shell(faces, names, parts.wall, "geometry.join.wall", taken), tolerance, repairs));
  // The wall's seams away from the body: through the root they would cut it open (no hole).
  const TopoDS_Shape wall = body_solids(one_shell(with_seams_away_from(wall_faces, centre_of(body_faces), tolerance, repairs)),
                                        tolerance, "geometry.join.wall: the wall", repairs);
  TopoDS_Shape body_part = with_crease_seams_split(body_faces, tolerance, names, repairs);
  if (body_cut) body_part = cut_body(body_part, *body_cut, tolerance, names, repairs);
  body_part = with_pinched_loops_inside_trimmed(body_part, wall, tolerance, names, repairs);
  body_part = with_closed_faces_halved(body_part, tolerance, names, repairs);
  const TopoDS_Shape body = body_solids(body_part, tolerance, "geometry.join.body: the body", repairs);
  if (const int left_out = faces.Extent() - taken.Extent(); left_out > 0)
    repairs.push_back("left out " + std::to_string(left_out) + " face(s) of the file that geometry.join does not name");

  // Their section first (a second on an OpenVSP wing): the distance between every pair of edges
  // (half a minute there) only to say how far apart parts that do not meet are.
  if (BRepAlgoAPI_Section section(body, wall); !section.IsDone() || !TopExp_Explorer(section.Shape(), TopAbs_EDGE).More())
    if (BRepExtrema_DistShapeShape apart(body, wall); apart.IsDone() && apart.Value() > tolerance) {
      const gp_Pnt p = apart.PointOnShape1(1);
      refuse("geometry.join: the body does not reach the wall: it comes within " + length_text(apart.Value()) +
             " of it, at (" + length_text(p.X()) + ", " + length_text(p.Y()) + ", " + length_text(p.Z()) + ")");
    }
  const TopoDS_Shape outer = far_solid(far, gp::DZ(), body, {});
  BRepAlgoAPI_Cut standing_out;
  require_inside(run(standing_out, body, wall, 0.1 * tolerance, "the body outside the wall part"), outer, far, tolerance,
                 /*others_outside=*/true);

  // One split of the three, the pieces chosen by side: the root curve is the parts' exact intersection.
  const DomainBySides domain = domain_by_sides(outer, body, wall, 0.1 * tolerance);
  TopExp_Explorer solid(domain.solids, TopAbs_SOLID);
  if (!solid.More()) refuse("geometry.join: the Boolean operations left no fluid domain");
  const TopoDS_Shape fluid = solid.Current();
  solid.Next();
  if (solid.More())
    refuse("geometry.join: the fluid domain falls apart into several pieces (does the far field cut the body?): " +
           pieces_text(domain.solids));
  names = joined_names(fluid, domain, names);
  return fluid;
}

}  // namespace semimesh::occ
