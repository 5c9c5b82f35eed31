#include "occ_surface.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <limits>

namespace semimesh::occ {
namespace {

cad::Vec3 to_vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

cad::SurfaceKind kind_of(GeomAbs_SurfaceType type) {
  switch (type) {
    case GeomAbs_Plane: return cad::SurfaceKind::Plane;
    case GeomAbs_Cylinder: return cad::SurfaceKind::Cylinder;
    case GeomAbs_Cone: return cad::SurfaceKind::Cone;
    case GeomAbs_Sphere: return cad::SurfaceKind::Sphere;
    case GeomAbs_Torus: return cad::SurfaceKind::Torus;
    case GeomAbs_BezierSurface: return cad::SurfaceKind::Bezier;
    case GeomAbs_BSplineSurface: return cad::SurfaceKind::BSpline;
    case GeomAbs_SurfaceOfRevolution: return cad::SurfaceKind::Revolution;
    case GeomAbs_SurfaceOfExtrusion: return cad::SurfaceKind::Extrusion;
    case GeomAbs_OffsetSurface: return cad::SurfaceKind::Offset;
    default: return cad::SurfaceKind::Other;
  }
}

}  // namespace

OccSurface::OccSurface(int id, std::string name, const TopoDS_Face& fluid_face)
    : cad::Surface(id, std::move(name), fluid_face.Orientation() == TopAbs_REVERSED ? -1 : +1),
      face_(TopoDS::Face(fluid_face.Oriented(TopAbs_FORWARD))) {
  surface_ = BRep_Tool::Surface(face_);  // location already applied
  if (surface_.IsNull())
    throw cad::CadError(cad::CadError::Kind::Geometry, "occ: face of surface " + std::to_string(id) + " has no surface");
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face_, u0, u1, v0, v1);
  bounds_ = {cad::Interval{u0, u1}, cad::Interval{v0, v1}};
  classifier_ = std::make_unique<BRepTopAdaptor_FClass2d>(face_, BRep_Tool::Tolerance(face_));
  GeomAbs_SurfaceType type = GeomAdaptor_Surface(surface_).GetType();
  kind_ = kind_of(type);
  mutable_evaluator_ = type == GeomAbs_SurfaceOfRevolution || type == GeomAbs_SurfaceOfExtrusion ||
                       type == GeomAbs_OffsetSurface;
}

cad::SurfaceDerivatives OccSurface::derivatives(const cad::Vec2& uv) const {
  gp_Pnt p;
  gp_Vec du, dv, duu, dvv, duv;
  surface_->D2(uv.x(), uv.y(), p, du, dv, duu, dvv, duv);
  return {to_vec(p.XYZ()), to_vec(du.XYZ()), to_vec(dv.XYZ()), to_vec(duu.XYZ()), to_vec(duv.XYZ()), to_vec(dvv.XYZ())};
}

bool OccSurface::contains(const cad::Vec2& uv) const {
  TopAbs_State state = classifier_->Perform(gp_Pnt2d(uv.x(), uv.y()));
  return state == TopAbs_IN || state == TopAbs_ON;
}

cad::SurfaceProjection OccSurface::project(const cad::Vec3& x, std::optional<cad::Vec2> guess) const {
  if (guess) return cad::Surface::project(x, guess);
  std::optional<cad::Vec2> best_inside, best_any;
  double d_inside = std::numeric_limits<double>::max(), d_any = d_inside;
  try {
    GeomAPI_ProjectPointOnSurf extrema(gp_Pnt(x.x(), x.y(), x.z()), surface_, bounds_[0].lo, bounds_[0].hi,
                                       bounds_[1].lo, bounds_[1].hi);
    for (int i = 1; i <= extrema.NbPoints(); ++i) {
      double u, v;
      extrema.Parameters(i, u, v);
      double d = extrema.Distance(i);
      cad::Vec2 uv(u, v);
      if (d < d_any) { d_any = d; best_any = uv; }
      if (d < d_inside && contains(uv)) { d_inside = d; best_inside = uv; }
    }
  } catch (const Standard_Failure&) {
    // OCC gave up (e.g. at a singular point): fall through to the generic sampled start.
  }
  if (best_inside) return cad::Surface::project(x, best_inside);
  if (best_any) return cad::Surface::project(x, best_any);
  return cad::Surface::project(x);
}

}  // namespace semimesh::occ
