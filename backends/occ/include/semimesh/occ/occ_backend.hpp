// The OpenCASCADE backend "occ": CAD files (STEP, IGES, BREP, FreeCAD .FCStd) or, without a file,
// the NACA wing on a wall built as OCC B-spline geometry, mapped onto the cadapi Model.
//
// Load parameters (Source::params):
//   occ.scale          number, default 1: multiplies every coordinate once, at load
//   occ.units          label of the resulting unit (default: the file's unit, e.g. "mm", or "file")
//   occ.sew            bool, default true: sew faces whose edges are free (BRepBuilderAPI_Sewing)
//   occ.sew_tolerance  number, default 1e-6 x bounding-box diagonal (after scaling)
//   occ.heal           bool, default true: ShapeFix_Shape + ShapeFix_Wireframe (small edges)
//   occ.fluid_inside   "auto" (default), "true" or "false": which side of the faces is fluid (see
//                      FluidSide)
//   occ.wall_plane     "px,py,pz,nx,ny,nz": a body-only file stands on this plane (normal into the
//                      fluid); with one of the three below, the fluid domain is built around it by
//                      Boolean operations (fluid_domain.hpp) and the fluid is inside it
//   occ.farfield_box   "xmin,ymin,zmin,xmax,ymax,zmax"; occ.farfield_sphere "cx,cy,cz,r";
//   occ.farfield_box_chords  k: a box k root chords around the body
//   occ.body_cut       "px,py,pz,nx,ny,nz": with a wall plane or a join, the body's part beyond this
//                      plane (the side the normal points to) taken away and the cut closed flat (a
//                      tip pinched to zero thickness made blunt)
//   naca.*             without a file: the analytic backend's wing keys (mock_cad::naca_params_from)
//
// Thread safety: queries build their OCC algorithm objects per call and share only immutable
// geometry, so the model is thread-safe. Surfaces of revolution/extrusion and offset surfaces,
// whose OCC evaluators may keep a mutable cache, are evaluated by each thread on its own copy;
// offset curves are not: a model holding one has Model::thread_safe() false.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/cad/source.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <TopoDS_Shape.hxx>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace semimesh::occ {

/// Which side of the faces the fluid lies on; decides the direction of every normal.
enum class FluidSide {
  /// Faces of a solid: fluid outside the solid. A closed shell that is not part of a solid
  /// (e.g. a wing on a wall inside a far-field box, as NekMesh's STEP files and the generated
  /// NACA wing): fluid inside the shell. Open shells and free faces: fluid on the side the face
  /// normal (with its orientation) points to.
  Auto,
  Outside,  ///< fluid outside every solid / closed shell
  Inside,   ///< fluid inside every solid / closed shell
};

struct ModelOptions {
  std::string units = "file";  ///< label of the coordinates' unit
  std::string units_origin;     ///< why (Model::units_origin)
  std::vector<std::string> repairs;  ///< what loading changed in the file (Model::repairs)
  double scale_applied = 1.0;  ///< factor already applied to the shape, reported by the model
  FluidSide fluid_side = FluidSide::Auto;
  /// Face names (faces matched with TopoDS_Shape::IsSame). Unnamed faces, and names that are
  /// empty or "NONE", become "face_<id>"; a name already taken gets "_<id>" appended.
  std::vector<std::pair<TopoDS_Shape, std::string>> face_names;
  /// Curve names, likewise (edges of the shape as given, matched with IsSame); unnamed edges
  /// become "edge_<id>".
  std::vector<std::pair<TopoDS_Shape, std::string>> edge_names;
};

/// Registry factory. source.path: .step/.stp/.iges/.igs/.brep/.brp/.fcstd (any case); empty path:
/// the B-spline NACA wing on a wall from the naca.* params. Throws cad::CadError naming the file.
std::unique_ptr<cad::Model> load_occ(const cad::Source& source);

/// Maps an OCC shape onto a cadapi Model: faces in TopExp::MapShapes order become surfaces
/// 0..n-1, edges become curves, vertices become vertices. Degenerated edges (poles) become
/// degenerate curves (Curve::is_degenerate) at their vertex, in the loops where the face uses them;
/// a face's seam edge is walked twice by its loop (Model::is_seam).
std::unique_ptr<cad::Model> model_from_shape(const TopoDS_Shape& shape, const std::string& backend_label,
                                             const ModelOptions& options = {});

/// The NACA wing on a wall inside a far-field box as one closed, sewn shell of B-spline and
/// planar faces around the fluid, faces in the analytic backend's surface order (upper, lower,
/// te_base when blunt, tip, then wall and box faces when present). Throws cad::CadError when
/// OCC fails to build or validate it.
TopoDS_Shape make_naca_wing_shape(const mock_cad::NacaWingParams& params);

/// Surface names of make_naca_wing_shape's faces, in face order.
std::vector<std::string> naca_wing_face_names(const mock_cad::NacaWingParams& params);

}  // namespace semimesh::occ
