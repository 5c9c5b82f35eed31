// An assembly whose body reaches into its wall part without being joined to it (occ.join_body,
// occ.join_wall with a far field box): the parts joined by OCCT's Booleans at load, and the bad
// input it refuses, each naming the key.
#include "fluid_domain.hpp"
#include "shape_measures.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/cad/labels.hpp"
#include "semimesh/occ/occ_backend.hpp"
#include "temp_path.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <GeomConvert.hxx>
#include <GeomFill_Generator.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Precision.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace semimesh::occ {
namespace {

// A cylinder of radius 1 along x from -5 to 5, its crest on z = 0, its seam along its bottom (the
// "fuselage") or along its crest.
TopoDS_Shape fuselage(bool seam_on_crest = false) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-5, 0, -1), gp::DX(), seam_on_crest ? gp::DZ() : -gp::DZ()), 1.0, 10.0)
      .Shape();
}

// The same as B-spline faces, as design tools export a fuselage (a rational B-spline closed, not
// periodic, in its angle).
TopoDS_Shape spline_fuselage(bool seam_on_crest) {
  return BRepBuilderAPI_NurbsConvert(fuselage(seam_on_crest), /*Copy=*/true).Shape();
}

// The B-spline fuselage's side alone, its parameters exchanged: closed in V, its angle (as OpenVSP
// writes a body of revolution), its flat ends left open (the join caps them).
TopoDS_Shape spline_fuselage_closed_in_v(bool seam_on_crest) {
  for (TopExp_Explorer f(spline_fuselage(seam_on_crest), TopAbs_FACE); f.More(); f.Next()) {
    auto side = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(f.Current()))->Copy());
    if (side.IsNull() || !(side->IsUClosed() || side->IsUPeriodic())) continue;
    side->ExchangeUV();
    return BRepBuilderAPI_MakeFace(side, Precision::Confusion()).Face();
  }
  ADD_FAILURE() << "no closed side";
  return {};
}

// The fuselage's side as OpenVSP writes one: a grid of untrimmed B-spline patches, a quarter turn
// each round (the first from the bottom, or from the crest) and half the length each along, its
// flat ends left open; faces in the order round, then along.
TopoDS_Shape patch_fuselage(bool seam_on_crest) {
  const Handle(Geom_CylindricalSurface) side =
      new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(-5, 0, -1), gp::DX(), seam_on_crest ? gp::DZ() : -gp::DZ()), 1.0);
  TopoDS_Compound patches;
  BRep_Builder builder;
  builder.MakeCompound(patches);
  for (int along = 0; along < 2; ++along)
    for (int round = 0; round < 4; ++round) {
      const Handle(Geom_RectangularTrimmedSurface) quarter = new Geom_RectangularTrimmedSurface(
          side, round * M_PI / 2, (round + 1) * M_PI / 2, 5.0 * along, 5.0 * (along + 1));
      builder.Add(patches, BRepBuilderAPI_MakeFace(GeomConvert::SurfaceToBSplineSurface(quarter), Precision::Confusion()).Face());
    }
  return patches;
}

enum class WallKind { Cylinder, BSpline, BSplineClosedInV, Patches };

TopoDS_Shape fuselage_of(WallKind kind, bool seam_on_crest) {
  switch (kind) {
    case WallKind::Cylinder: return fuselage(seam_on_crest);
    case WallKind::BSpline: return spline_fuselage(seam_on_crest);
    case WallKind::BSplineClosedInV: return spline_fuselage_closed_in_v(seam_on_crest);
    case WallKind::Patches: return patch_fuselage(seam_on_crest);
  }
  return {};
}

// The parts side by side in one BREP file, not joined.
std::string file_of(const TopoDS_Shape& body, const TopoDS_Shape& wall, const std::string& name) {
  TopoDS_Compound parts;
  BRep_Builder builder;
  builder.MakeCompound(parts);
  builder.Add(parts, body);
  builder.Add(parts, wall);
  const std::string path = semimesh::test::temp_path(name).string();
  EXPECT_TRUE(BRepTools::Write(parts, path.c_str()));
  return path;
}

// A block 1 x 0.2 x 2.3 (the "wing", faces #0-#5) standing 0.3 deep in the fuselage (faces #6-#8:
// side and flat ends; #6 alone when closed in V); `lift` raises the block.
std::string assembly_file(double lift = 0.0, bool seam_on_crest = false, WallKind wall = WallKind::Cylinder) {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, -0.1, -0.3 + lift), gp_Pnt(1, 0.1, 2 + lift)).Shape();
  return file_of(block, fuselage_of(wall, seam_on_crest),
                 "wall" + std::to_string(static_cast<int>(wall)) + "_" +
                     (seam_on_crest ? "assembly_crest.brep" : lift == 0.0 ? "assembly.brep" : "assembly_apart.brep"));
}

const std::vector<std::pair<std::string, std::string>> kJoin = {
    {"occ.join_body", "#0\n#1\n#2\n#3\n#4\n#5\n"}, {"occ.join_wall", "#6\n#7\n#8\n"}, {"occ.farfield_box", "-4,-4,-4,4,4,4"}};

std::unique_ptr<cad::Model> load_assembly(const std::vector<std::pair<std::string, std::string>>& params, double lift = 0.0) {
  cad::Source source{assembly_file(lift), {}};
  for (const auto& [key, value] : params) source.params.set(key, value);
  return load_occ(source);
}

std::string assembly_error_of(std::vector<std::pair<std::string, std::string>> params, double lift = 0.0) {
  try {
    load_assembly(params, lift);
  } catch (const cad::CadError& e) {
    EXPECT_EQ(e.kind(), cad::CadError::Kind::BadParameter);
    return e.what();
  }
  ADD_FAILURE() << "no CadError";
  return {};
}

std::vector<std::pair<std::string, std::string>> join_with(std::vector<std::pair<std::string, std::string>> params,
                                                           const std::string& key, const std::string& value) {
  for (auto& [k, v] : params)
    if (k == key) {
      v = value;
      return params;
    }
  params.emplace_back(key, value);
  return params;
}

TEST(OccJoinParts, TheWallHoldsTheBodysRootAsAHole) {
  const auto model = load_assembly(kJoin);
  // The box's six faces, the cylinder's side between them, the block's four sides and its top (its
  // bottom lies inside the cylinder): 12 faces, every curve bounding two of them.
  EXPECT_EQ(model->num_surfaces(), 12);
  for (int c = 0; c < model->num_curves(); ++c) {
    EXPECT_EQ(model->surfaces_of_curve(c).size(), 2u) << cad::curve_label(*model, c);
  }
  const std::optional<int> wall = model->find_surface("wall");
  ASSERT_TRUE(wall.has_value());
  EXPECT_EQ(model->loops(*wall).size(), 2u) << "the outer boundary and the block's root";
  EXPECT_FALSE(model->surface(*wall).is_planar());
  int far = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) far += model->surface(s).name().rfind("farfield_", 0) == 0;
  EXPECT_EQ(far, 6);
  // The root curve is the exact intersection: its points on the cylinder and on the block's sides.
  for (const cad::CurveUse& use : model->loops(*wall)[1].uses) {
    const cad::Curve& curve = model->curve(use.curve);
    const cad::Interval b = curve.bounds();
    for (int i = 0; i <= 8; ++i) {
      const cad::Vec3 p = curve.point(b.lo + b.length() * i / 8);
      EXPECT_NEAR(std::hypot(p.y(), p.z() + 1.0), 1.0, 1e-6) << "on the cylinder";
      EXPECT_TRUE(std::abs(std::abs(p.y()) - 0.1) < 1e-6 || std::abs(p.x()) < 1e-6 || std::abs(p.x() - 1) < 1e-6)
          << "on a side of the block";
    }
  }
}

// A fuselage whose seam runs along its crest, through the block's root: joined as it is, the root
// loop would be cut open along the seam and become part of the wall's outer boundary. The wall is
// re-seamed on its far side first: the same cylinder turned half a turn about its axis, the same
// B-spline with its origin half a period round (the parameter: a B-spline fuselage), also when the
// B-spline's closed parameter is V (its parameters are exchanged).
class OccJoinSeam : public ::testing::TestWithParam<WallKind> {};

TEST_P(OccJoinSeam, AWallSeamThroughTheRootIsMovedAway) {
  cad::Source source{assembly_file(0.0, /*seam_on_crest=*/true, GetParam()), {}};
  for (const auto& [key, value] : kJoin) source.params.set(key, value);
  if (GetParam() == WallKind::BSplineClosedInV) source.params.set("occ.join_wall", "#6\n");
  const auto model = load_occ(source);
  const std::optional<int> wall = model->find_surface("wall");
  ASSERT_TRUE(wall.has_value());
  EXPECT_EQ(model->loops(*wall).size(), 2u) << "the root is a hole of the wall";
  EXPECT_TRUE(std::any_of(model->repairs().begin(), model->repairs().end(), [](const std::string& r) {
    return r.find("moved the seam of 1 face(s)") != std::string::npos;
  }));
  // The wall's fluid normal still points out of the fuselage (re-seaming in V flips the surface's own).
  const cad::SurfaceProjection crest = model->surface(*wall).project(cad::Vec3(-2, 0, 0));
  EXPECT_GT(model->surface(*wall).normal(crest.uv).z(), 0.99) << "on the crest, into the fluid";
  // The seam now runs along the bottom (z = -2), half a turn from the root.
  int seams = 0;
  for (int c = 0; c < model->num_curves(); ++c) {
    const auto& uses = model->surfaces_of_curve(c);
    if (uses.size() != 2 || uses[0].surface != *wall || uses[1].surface != *wall) continue;
    ++seams;
    const cad::Interval b = model->curve(c).bounds();
    for (int i = 0; i <= 4; ++i) {
      const cad::Vec3 p = model->curve(c).point(b.lo + b.length() * i / 4);
      EXPECT_NEAR(p.z(), -2.0, 1e-7) << cad::curve_label(*model, c);
      EXPECT_NEAR(p.y(), 0.0, 1e-7) << cad::curve_label(*model, c);
    }
  }
  EXPECT_EQ(seams, 1);
}

INSTANTIATE_TEST_SUITE_P(CylinderAndBSpline, OccJoinSeam,
                         ::testing::Values(WallKind::Cylinder, WallKind::BSpline, WallKind::BSplineClosedInV),
                         [](const ::testing::TestParamInfo<WallKind>& info) {
                           switch (info.param) {
                             case WallKind::Cylinder: return "Cylinder";
                             case WallKind::BSpline: return "BSpline";
                             case WallKind::BSplineClosedInV: return "BSplineClosedInV";
                             case WallKind::Patches: return "Patches";
                           }
                           return "";
                         });

// The re-seamed B-spline wall is the file's surface, only started elsewhere (its seam half a turn
// round: AWallSeamThroughTheRootIsMovedAway/BSpline): its points lie on the file's fuselage and the
// file's points (between the box's ends) on it, to 1e-9.
TEST(OccJoinParts, ABSplineWallIsReseamedExactly) {
  cad::Source source{assembly_file(0.0, /*seam_on_crest=*/true, WallKind::BSpline), {}};
  for (const auto& [key, value] : kJoin) source.params.set(key, value);
  const auto model = load_occ(source);
  EXPECT_TRUE(std::any_of(model->repairs().begin(), model->repairs().end(), [](const std::string& r) {
    return r.find("moved the seam of 1 face(s)") != std::string::npos;
  }));
  const std::optional<int> wall = model->find_surface("wall");
  ASSERT_TRUE(wall.has_value());
  EXPECT_EQ(model->loops(*wall).size(), 2u) << "the root is a hole of the wall";
  const cad::Surface& surface = model->surface(*wall);
  EXPECT_EQ(surface.kind(), cad::SurfaceKind::BSpline);
  // The file's fuselage: radius 1 about the line y = 0, z = -1 (its points measured against it),
  // and its own B-spline side, sampled at parameters.
  const TopoDS_Shape file = spline_fuselage(/*seam_on_crest=*/true);
  Handle(Geom_Surface) side;
  for (TopExp_Explorer f(file, TopAbs_FACE); f.More(); f.Next()) {
    const Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(f.Current()));
    if (s->IsUClosed() || s->IsUPeriodic()) side = s;
  }
  ASSERT_FALSE(side.IsNull());
  const auto box = surface.bounds();
  double u0, u1, v0, v1;
  side->Bounds(u0, u1, v0, v1);
  double worst_on_file = 0.0, worst_on_wall = 0.0;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 8; ++j) {
      const cad::Vec3 p = surface.point({box[0].lo + box[0].length() * i / 16, box[1].lo + box[1].length() * j / 8});
      GeomAPI_ProjectPointOnSurf onto(gp_Pnt(p.x(), p.y(), p.z()), side);
      ASSERT_GT(onto.NbPoints(), 0);
      worst_on_file = std::max(worst_on_file, onto.LowerDistance());
      const gp_Pnt q = side->Value(u0 + (u1 - u0) * i / 16, v0 + (v1 - v0) * (0.1 + 0.8 * j / 8));
      if (std::abs(q.X()) > 3.9) continue;  // past the box's ends
      const cad::Vec3 x(q.X(), q.Y(), q.Z());
      worst_on_wall = std::max(worst_on_wall, (surface.point(surface.project(x).uv) - x).norm());
    }
  EXPECT_LT(worst_on_file, 1e-9);
  EXPECT_LT(worst_on_wall, 1e-9);
}

// A fuselage in eight patches (two along, four round): joined into one wall face before the join,
// its control points kept (the points of the wall lie on the cylinder), the root a hole in it.
// Without the joining the root would lie on one patch and the wall layer end on its neighbours.
TEST(OccJoinParts, AFuselageInPatchesBecomesOneWallFace) {
  for (bool seam_on_crest : {false, true}) {
    cad::Source source{assembly_file(0.0, seam_on_crest, WallKind::Patches), {}};
    for (const auto& [key, value] : kJoin) source.params.set(key, value);
    source.params.set("occ.join_wall", "#6\n#7\n#8\n#9\n#10\n#11\n#12\n#13\n");
    const auto model = load_occ(source);
    EXPECT_TRUE(std::any_of(model->repairs().begin(), model->repairs().end(), [](const std::string& r) {
      return r.find("joined 8 patches of the wall part into 1 face(s)") != std::string::npos;
    })) << "seam on crest " << seam_on_crest;
    EXPECT_EQ(model->num_surfaces(), 12) << "the box's six, one wall, the block's five";
    const std::optional<int> wall = model->find_surface("wall");
    ASSERT_TRUE(wall.has_value());
    EXPECT_EQ(model->loops(*wall).size(), 2u) << "the root is a hole of the wall";
    const cad::Surface& surface = model->surface(*wall);
    const auto box = surface.bounds();
    double worst = 0.0;
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 8; ++j) {
        const cad::Vec3 p = surface.point({box[0].lo + box[0].length() * i / 16, box[1].lo + box[1].length() * j / 8});
        worst = std::max(worst, std::abs(std::hypot(p.y(), p.z() + 1.0) - 1.0));
      }
    EXPECT_LT(worst, 1e-12) << "the patches' own control points";
    const cad::SurfaceProjection crest = surface.project(cad::Vec3(-2, 0, 0));
    EXPECT_GT(surface.normal(crest.uv).z(), 0.99) << "on the crest, into the fluid";
    for (int c = 0; c < model->num_curves(); ++c)
      EXPECT_EQ(model->surfaces_of_curve(c).size(), 2u) << cad::curve_label(*model, c) << ": the domain is closed";
  }
}

TEST(OccJoinParts, ASeamAwayFromTheRootIsKept) {
  const auto model = load_assembly(kJoin);
  EXPECT_TRUE(std::none_of(model->repairs().begin(), model->repairs().end(), [](const std::string& r) {
    return r.find("moved the seam") != std::string::npos;
  }));
}

TEST(OccJoinParts, FacesLeftOutAreSaid) {
  // The block's top named twice would be refused; the cylinder's flat ends left out of the wall part:
  // they lie outside the box, so the domain is the same, and the repair says two faces were left out.
  const auto model = load_assembly(join_with(kJoin, "occ.join_wall", "#6\n"));
  EXPECT_TRUE(model->find_surface("wall").has_value());
  EXPECT_TRUE(std::any_of(model->repairs().begin(), model->repairs().end(), [](const std::string& r) {
    return r.find("left out 2 face(s)") != std::string::npos;
  }));
}

TEST(OccJoinParts, BadPartsAreRefusedNamingTheKey) {
  EXPECT_NE(assembly_error_of(join_with(kJoin, "occ.join_body", "#0\n#99\n")).find("geometry.join.body: no face #99"), std::string::npos);
  EXPECT_NE(assembly_error_of(join_with(kJoin, "occ.join_body", "wing\n")).find("geometry.join.body: no face named 'wing'"),
            std::string::npos);
  EXPECT_NE(assembly_error_of(join_with(kJoin, "occ.join_wall", "#5\n#6\n#7\n#8\n")).find("named twice"), std::string::npos);
  EXPECT_NE(assembly_error_of(kJoin, /*lift=*/3.0).find("geometry.join: the body does not reach the wall"), std::string::npos);
  // The wing's bottom face left out: the block is open along a planar loop, closed again by a cap.
  EXPECT_NO_THROW(load_assembly(join_with(kJoin, "occ.join_body", "#0\n#1\n#2\n#3\n#5\n")));
}

TEST(OccJoinParts, TheFarFieldMustBeABoxOrASphereHoldingTheBody) {
  auto chords = join_with(kJoin, "occ.farfield_box_chords", "3");
  chords.erase(std::remove_if(chords.begin(), chords.end(), [](const auto& kv) { return kv.first == "occ.farfield_box"; }),
               chords.end());
  EXPECT_NE(assembly_error_of(chords).find("box or a sphere"), std::string::npos);
  EXPECT_NE(assembly_error_of(join_with(kJoin, "occ.farfield_box", "-4,-4,-4,4,4,1")).find("does not contain the body"), std::string::npos);
  EXPECT_NE(assembly_error_of(join_with(kJoin, "occ.wall_plane", "0,0,0,0,0,1")).find("exclude each other"), std::string::npos);
  auto no_far = kJoin;
  no_far.pop_back();
  EXPECT_NE(assembly_error_of(no_far).find("go together"), std::string::npos);
}

// One face lofted through two elliptic sections about x = 0.5 (half-axis 0.5 along x, `minor`
// along y), at z = -0.3 (inside the fuselage) and z = 2: closed round its sections, its seam on the
// ellipse's smooth end.
TopoDS_Face elliptic_skin(double minor_root, double minor_top) {
  GeomFill_Generator loft;
  for (const auto& [z, minor] : {std::pair{-0.3, minor_root}, std::pair{2.0, minor_top}})
    loft.AddCurve(GeomConvert::CurveToBSplineCurve(new Geom_Ellipse(gp_Ax2(gp_Pnt(0.5, 0, z), gp::DZ(), gp::DX()), 0.5, minor)));
  loft.Perform(Precision::Confusion());
  return BRepBuilderAPI_MakeFace(loft.Surface(), Precision::Confusion()).Face();
}

// `skin` (#0) joined to the fuselage (#1-#3) in the box [-4, 4]^3.
TopoDS_Shape joined_to_fuselage(const TopoDS_Face& skin, FaceNames& names, std::vector<std::string>& repairs) {
  TopoDS_Compound parts;
  BRep_Builder builder;
  builder.MakeCompound(parts);
  builder.Add(parts, skin);
  builder.Add(parts, fuselage());
  FarFieldShape far;
  far.box = std::array<double, 6>{-4, -4, -4, 4, 4, 4};
  far.label = "box";
  return fluid_domain_of_parts(parts, PartsToJoin{{"#0"}, {"#1", "#2", "#3"}}, far, std::nullopt, 1e-6, names, repairs);
}

// A "wing" lofted from a section pinched flat at its root (an ellipse of minor radius 1e-9, inside
// the fuselage) to an open elliptic tip: its root loop runs out and back along itself, enclosing no
// area, so no face closes it (an OpenVSP wing whose root section has zero thickness). Before the
// check, a cap of zero area was sewn on and the Booleans returned a domain with dangling curves;
// then it was refused; now the pinched end, inside the fuselage, is trimmed back inside it and
// capped there, which leaves the joined shape as it was: the domain is the box minus the
// fuselage minus the wing's part above it.
TEST(OccJoinParts, APinchedLoopInsideTheWallPartIsTrimmedInsideIt) {
  FaceNames names;
  std::vector<std::string> repairs;
  const TopoDS_Shape domain = joined_to_fuselage(elliptic_skin(1e-9, 0.1), names, repairs);
  ASSERT_TRUE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("trimmed the body's free loop pinched to zero thickness") != std::string::npos;
  })) << "no trim among the repairs";
  // The wing's elliptic sections have half-axes 0.5 and 0.1 (z + 0.3) / 2.3, linear in z (two
  // sections): above the fuselage's crest (z = 0; the crest's fall within the wing's 0.1 thickness
  // is under 0.005) its volume is pi 0.5 0.1 / 2.3 times the integral of (z + 0.3) from 0 to 2.
  const double wing_above = M_PI * 0.05 / 2.3 * (2.0 + 0.6);
  EXPECT_NEAR(std::abs(test::volume_of(domain)), 512.0 - M_PI * 8.0 - wing_above, 2e-3);
}

// A strut of elliptic section (half-axes 0.5 along x, 0.1 along y, from z = -0.3 to 2) as one
// face closed round its sections, its seam on the smooth end of the ellipse (not a crease: kept by
// the crease split), standing in the fuselage. The join cuts the closed face in two first (OCCT's
// general fuse left such a face whole where the fuselage crosses it: trelau/AFEM's GT delta): two
// body faces carry its name, and the domain is the box minus the fuselage minus the strut above it.
TEST(OccJoinParts, AClosedBodyFaceIsCutInTwoBeforeTheJoin) {
  const TopoDS_Face skin = elliptic_skin(0.1, 0.1);
  FaceNames names{{skin, "strut"}};
  std::vector<std::string> repairs;
  const TopoDS_Shape domain = joined_to_fuselage(skin, names, repairs);
  EXPECT_TRUE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("cut 1 closed face(s) of the body in two") != std::string::npos;
  })) << "no cut among the repairs";
  int strut_faces = 0;
  for (TopExp_Explorer f(domain, TopAbs_FACE); f.More(); f.Next())
    strut_faces += std::any_of(names.begin(), names.end(), [&](const auto& n) {
      return n.second == "strut" && n.first.IsSame(f.Current());
    });
  EXPECT_EQ(strut_faces, 2) << "the two halves of the skin, both named";
  // Above the fuselage (z = -1 + sqrt(1 - y^2)) up to z = 2, over the ellipse: with y = 0.1 sin t,
  // the chord at y is 2 0.5 cos t, so the volume is the integral over t of 0.1 cos t times
  // (3 - sqrt(1 - y^2)) cos t (Simpson, 2000 intervals: smooth in t).
  const int n = 2000;
  double strut_above = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = -M_PI / 2 + M_PI * i / n, y = 0.1 * std::sin(t);
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    strut_above += weight * 0.1 * std::cos(t) * std::cos(t) * (3.0 - std::sqrt(1.0 - y * y));
  }
  strut_above *= M_PI / n / 3.0;
  EXPECT_NEAR(std::abs(test::volume_of(domain)), 512.0 - M_PI * 8.0 - strut_above, 1e-6);
}

}  // namespace
}  // namespace semimesh::occ
