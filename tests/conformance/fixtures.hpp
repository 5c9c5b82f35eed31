// The models the conformance suite runs on: one type per model, each saying how to load it and
// what is known about it (closedness, where the fluid is, analytic values to compare with).
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mock_cad/naca.hpp"
#ifdef SEMIMESH_HAVE_OCC
#include "semimesh/occ/occ_backend.hpp"

#include <BRepPrimAPI_MakeSphere.hxx>
#endif
#ifdef SEMIMESH_HAVE_VENDOR_FAKE
#include "semimesh/vendor/vendor_backend.hpp"
#endif

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace conformance {

namespace cad = semimesh::cad;

struct Expectations {
  /// Watertight: every curve bounds two surfaces, once forward and once reversed.
  bool closed = true;
  /// The model encloses the fluid (far-field box): fluid points have winding number -1; else the
  /// fluid is outside a body and has winding number 0.
  bool fluid_encloses = true;
  /// Leading-edge radius of the sections, when known; the leading edge must then be the z axis
  /// (unswept, x = y = 0) and the surface on its upper side be named "upper".
  std::optional<double> le_radius;
  double le_radius_tolerance = 1e-9;  ///< relative
  /// Faces whose fluid side is checked by the winding number (0: all). That integral calls the
  /// trim test thousands of times, ~0.2 ms each on OCC's B-spline-trimmed faces; the other faces
  /// follow from the loop-orientation test.
  int winding_surfaces = 0;
  /// Why the closedness checks do not apply (when closed is false).
  std::string open_reason;
  /// Numbers of seam curves (used twice by one face) and of degenerate curves (poles), when known.
  std::optional<int> seams, poles;
};

inline std::string testdata(const std::string& file) { return std::string(SEMIMESH_TESTDATA_DIR) + "/cad/" + file; }

/// Empty when the file exists, else the reason to skip.
inline std::string missing(const std::string& path) {
  return std::filesystem::exists(path) ? "" : "test CAD file " + path + " not found (see shared/testdata/cad/README.md)";
}

/// Models without periodic faces: no seam, no pole.
inline Expectations smooth_wing(Expectations e = {}) {
  e.seams = 0;
  e.poles = 0;
  return e;
}

/// A body of revolution: one periodic face, one seam, two poles; fluid outside.
inline Expectations revolved_body() {
  Expectations e;
  e.fluid_encloses = false;
  e.seams = 1;
  e.poles = 2;
  return e;
}

struct NacaDefault {
  static constexpr const char* kName = "naca default (0012, blunt TE, box)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() { return semimesh::mock_cad::load_naca(cad::Source{}); }
  static Expectations expect() {
    Expectations e;
    // NACA 4-digit: y_t = 5t(0.2969 sqrt(x) + ...) ~ sqrt(2 r x) near the LE, so
    // r = (5 * 0.2969 t)^2 / 2 = 1.1019 t^2 c (Abbott & von Doenhoff 1959, sec. 6.4).
    e.le_radius = 0.5 * std::pow(5 * 0.2969 * 0.12, 2);
    return smooth_wing(e);
  }
};

inline const cad::Params kRevolutionKeys = {
    {"naca.shape", "revolution"}, {"naca.code", "0012"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}, {"naca.chord", "2"}};

struct NacaRevolution {
  static constexpr const char* kName = "naca body of revolution (0012, seam and two poles)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() { return semimesh::mock_cad::load_naca(cad::Source{"", kRevolutionKeys}); }
  static Expectations expect() { return revolved_body(); }
};

struct NacaBluntNoBox {
  static constexpr const char* kName = "naca 0015 blunt TE, no box";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(
        cad::Source{"", {{"naca.code", "0015"}, {"naca.te", "blunt"}, {"naca.farfield", "false"}, {"naca.chord", "2"}}});
  }
  static Expectations expect() {
    Expectations e;
    e.closed = false;
    e.fluid_encloses = false;
    e.open_reason = "without the wall the root section is an open boundary";
    e.le_radius = 0.5 * std::pow(5 * 0.2969 * 0.15, 2) * 2.0;
    return smooth_wing(e);
  }
};

struct NacaCamberedTaperedSweptSharp {
  static constexpr const char* kName = "naca 2412 sharp TE, taper 0.5, sweep 25 deg";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{
        "", {{"naca.code", "2412"}, {"naca.te", "sharp"}, {"naca.taper", "0.5"}, {"naca.sweep", "25"}, {"naca.span", "2"}}});
  }
  static Expectations expect() { return smooth_wing(); }
};

/// Rounded tips (naca.tip = round): a pole at the tip's leading edge, and a second one at a sharp
/// trailing edge; a blunt base capped by a half disc.
inline Expectations rounded_tip(int poles, Expectations e = {}) {
  e.seams = 0;
  e.poles = poles;
  return e;
}

struct NacaRoundTipBlunt {
  static constexpr const char* kName = "naca 0012 blunt TE, rounded tip";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"", {{"naca.tip", "round"}, {"naca.span", "2"}}});
  }
  static Expectations expect() {
    Expectations e;
    e.le_radius = NacaDefault::expect().le_radius;
    return rounded_tip(1, e);
  }
};

struct NacaRoundTipBluntTaperedSwept {
  static constexpr const char* kName = "naca 0015 blunt TE, rounded tip, taper 0.6, sweep 20 deg";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{
        "", {{"naca.code", "0015"}, {"naca.tip", "round"}, {"naca.taper", "0.6"}, {"naca.sweep", "20"}, {"naca.span", "2"}}});
  }
  static Expectations expect() { return rounded_tip(1); }
};

struct NacaRoundTipCamberedTaperedSweptSharp {
  static constexpr const char* kName = "naca 2412 sharp TE, rounded tip, taper 0.5, sweep 25 deg";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"",
                                                     {{"naca.code", "2412"},
                                                      {"naca.te", "sharp"},
                                                      {"naca.tip", "round"},
                                                      {"naca.taper", "0.5"},
                                                      {"naca.sweep", "25"},
                                                      {"naca.span", "2"}}});
  }
  static Expectations expect() { return rounded_tip(2); }
};

/// A wing on a fuselage (naca.wall = cylinder or cone): the wall is periodic about the fuselage's axis,
/// with one seam (its bottom line) and no pole.
inline Expectations on_cylinder(Expectations e = {}) {
  e.seams = 1;
  e.poles = 0;
  return e;
}

struct NacaOnCylinderBlunt {
  static constexpr const char* kName = "naca on cylinder (0012 blunt)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"", {{"naca.wall", "cylinder"}, {"naca.span", "2"}}});
  }
  static Expectations expect() {
    Expectations e;
    e.le_radius = NacaDefault::expect().le_radius;
    return on_cylinder(e);
  }
};

struct NacaOnCylinderCamberedTaperedSweptSharp {
  static constexpr const char* kName = "naca on cylinder (2412 sharp TE, taper 0.5, sweep 25 deg, radius 0.8)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"",
                                                     {{"naca.wall", "cylinder"},
                                                      {"naca.wall_radius", "0.8"},
                                                      {"naca.code", "2412"},
                                                      {"naca.te", "sharp"},
                                                      {"naca.taper", "0.5"},
                                                      {"naca.sweep", "25"},
                                                      {"naca.span", "2"}}});
  }
  static Expectations expect() { return on_cylinder(); }
};

/// A cambered blunt base: its lower and upper root corners sit at different heights on the cylinder.
struct NacaOnCylinderCamberedTaperedSweptBlunt {
  static constexpr const char* kName = "naca on cylinder (4415 blunt TE, taper 1.4, sweep -15 deg, radius 0.5)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"",
                                                     {{"naca.wall", "cylinder"},
                                                      {"naca.wall_radius", "0.5"},
                                                      {"naca.code", "4415"},
                                                      {"naca.taper", "1.4"},
                                                      {"naca.sweep", "-15"},
                                                      {"naca.span", "2"}}});
  }
  static Expectations expect() { return on_cylinder(); }
};

/// Dihedral (naca.dihedral) shears the wing sideways: the junction angle differs on its two sides.
struct NacaOnCylinderDihedral {
  static constexpr const char* kName = "naca on cylinder (2412 blunt TE, dihedral 15 deg, taper 0.7, radius 1)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"",
                                                     {{"naca.wall", "cylinder"},
                                                      {"naca.wall_radius", "1"},
                                                      {"naca.code", "2412"},
                                                      {"naca.dihedral", "15"},
                                                      {"naca.taper", "0.7"},
                                                      {"naca.span", "2"}}});
  }
  static Expectations expect() { return on_cylinder(); }
};

/// A cone (naca.wall = cone) narrowing downstream under a swept, tapered sharp wing.
struct NacaOnConeSweptSharp {
  static constexpr const char* kName = "naca on cone (0012 sharp TE, sweep 20 deg, taper 0.6, half angle -3 deg)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{"",
                                                     {{"naca.wall", "cone"},
                                                      {"naca.wall_angle", "-3"},
                                                      {"naca.te", "sharp"},
                                                      {"naca.sweep", "20"},
                                                      {"naca.taper", "0.6"},
                                                      {"naca.span", "2"}}});
  }
  static Expectations expect() { return on_cylinder(); }
};

/// ... and widening downstream under a cambered blunt wing.
struct NacaOnConeCamberedBlunt {
  static constexpr const char* kName = "naca on cone (2412 blunt TE, half angle 6 deg, radius 1.2)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(cad::Source{
        "", {{"naca.wall", "cone"}, {"naca.wall_angle", "6"}, {"naca.wall_radius", "1.2"}, {"naca.code", "2412"}, {"naca.span", "2"},
             {"naca.box", "-6,-9,-12,7,9,8"}}});
  }
  static Expectations expect() { return on_cylinder(); }
};

struct NacaDihedralSharp {
  static constexpr const char* kName = "naca 0012 sharp TE, dihedral -8 deg";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::mock_cad::load_naca(
        cad::Source{"", {{"naca.te", "sharp"}, {"naca.dihedral", "-8"}, {"naca.span", "2"}}});
  }
  static Expectations expect() { return smooth_wing(); }
};

#ifdef SEMIMESH_HAVE_OCC
struct OccNaca {
  static constexpr const char* kName = "occ B-spline NACA 0012 wing";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() { return semimesh::occ::load_occ(cad::Source{}); }
  static Expectations expect() {
    Expectations e;
    e.le_radius = NacaDefault::expect().le_radius;
    e.le_radius_tolerance = 1e-2;  // B-spline fit of the section: curvature is approximate
    e.winding_surfaces = 2;
    return smooth_wing(e);
  }
};

/// OCC's own sphere: periodic in u (seam on the meridian u = 0), poles at v = +-pi/2.
struct OccSphere {
  static constexpr const char* kName = "occ sphere (BRepPrimAPI)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::occ::model_from_shape(BRepPrimAPI_MakeSphere(1.5).Shape(), "occ");
  }
  static Expectations expect() { return revolved_body(); }
};

struct OccStepNektarWing {
  static constexpr const char* kName = "occ STEP nektar_3d_bl_wing_naca0012";
  static std::string path() { return testdata("nektar_3d_bl_wing_naca0012.stp"); }
  static std::string skip_reason() { return missing(path()); }
  static std::unique_ptr<cad::Model> load() { return semimesh::occ::load_occ(cad::Source{path(), {}}); }
  static Expectations expect() {
    Expectations e;
    e.winding_surfaces = 2;
    return e;
  }
};

struct OccStepOneraM6 {
  static constexpr const char* kName = "occ STEP onera_m6_sharp_te";
  static std::string path() { return testdata("onera_m6_sharp_te.stp"); }
  static std::string skip_reason() { return missing(path()); }
  static std::unique_ptr<cad::Model> load() { return semimesh::occ::load_occ(cad::Source{path(), {}}); }
  static Expectations expect() {
    Expectations e;
    e.fluid_encloses = false;  // one closed solid: the fluid is outside it
    e.winding_surfaces = 2;
    return e;
  }
};

/// The same body-only file on its wall plane y = 0 inside a box of 5 chords, built by OCCT's Booleans
/// (occ.wall_plane, geometry.wall_plane in a config): an ordinary fluid-enclosing model.
struct OccStepOneraM6OnWall {
  static constexpr const char* kName = "occ STEP onera_m6_sharp_te on the wall y = 0 in a box";
  static std::string skip_reason() { return missing(OccStepOneraM6::path()); }
  static std::unique_ptr<cad::Model> load() {
    cad::Source source{OccStepOneraM6::path(), {}};
    source.params.set("occ.wall_plane", "0,0,0,0,1,0");
    source.params.set("occ.farfield_box_chords", "5");
    return semimesh::occ::load_occ(source);
  }
  static Expectations expect() {
    Expectations e;
    e.winding_surfaces = 2;
    e.seams = 0;
    e.poles = 0;
    return e;
  }
};

/// ... and in a half sphere (its axis along the wall's normal): a seam and a pole on the far field.
struct OccStepOneraM6InSphere {
  static constexpr const char* kName = "occ STEP onera_m6_sharp_te on the wall y = 0 in a half sphere";
  static std::string skip_reason() { return missing(OccStepOneraM6::path()); }
  static std::unique_ptr<cad::Model> load() {
    cad::Source source{OccStepOneraM6::path(), {}};
    source.params.set("occ.wall_plane", "0,0,0,0,1,0");
    source.params.set("occ.farfield_sphere", "400,0,0,8000");
    return semimesh::occ::load_occ(source);
  }
  static Expectations expect() {
    Expectations e;
    e.winding_surfaces = 2;
    e.seams = 1;
    e.poles = 1;
    return e;
  }
};
#endif

#ifdef SEMIMESH_HAVE_VENDOR_FAKE
struct VendorFake {
  static constexpr const char* kName = "vendor adapter over the fake kernel (NACA 0012)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    return semimesh::vendor::load_vendor(cad::Source{"naca:naca.code=0012;naca.span=2", {}});
  }
  static Expectations expect() {
    Expectations e;
    e.le_radius = NacaDefault::expect().le_radius;
    return smooth_wing(e);
  }
};

struct VendorFakeRevolution {
  static constexpr const char* kName = "vendor adapter over the fake kernel (body of revolution)";
  static std::string skip_reason() { return {}; }
  static std::unique_ptr<cad::Model> load() {
    std::string path = "naca:";
    for (const auto& [key, value] : kRevolutionKeys.all()) path += key + "=" + value + ";";
    return semimesh::vendor::load_vendor(cad::Source{path, {}});
  }
  static Expectations expect() { return revolved_body(); }
};
#endif

}  // namespace conformance
