// OccSurface::is_planar by geometry: CAD tools export planar walls and box faces as B-splines, and
// a wall must be found planar whatever the surface's type (issue: your own wing CAD as it comes).
#include "occ_surface.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Precision.hxx>
#include <gp.hxx>
#include <gp_Ax3.hxx>

#include <gtest/gtest.h>

namespace semimesh::occ {
namespace {

// A tilted plane through (1, 2, 3) as an OCC surface, size 10.
Handle(Geom_Plane) tilted_plane() { return new Geom_Plane(gp_Ax3(gp_Pnt(1, 2, 3), gp_Dir(0.3, -0.2, 1.0))); }

Handle(Geom_BSplineSurface) as_bspline(const Handle(Geom_Surface)& s, double half) {
  return GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(s, -half, half, -half, half));
}

OccSurface surface_of(const Handle(Geom_Surface)& s, double u0, double u1, double v0, double v1) {
  return OccSurface(0, "s", BRepBuilderAPI_MakeFace(s, u0, u1, v0, v1, Precision::Confusion()).Face());
}

TEST(OccPlanar, PlaneIsPlanar) {
  const OccSurface s = surface_of(tilted_plane(), -5, 5, -5, 5);
  EXPECT_EQ(s.kind(), cad::SurfaceKind::Plane);
  EXPECT_TRUE(s.is_planar());
}

TEST(OccPlanar, PlanarBSplineIsPlanarAndStaysABSpline) {
  const OccSurface s = surface_of(as_bspline(tilted_plane(), 5), -5, 5, -5, 5);
  EXPECT_EQ(s.kind(), cad::SurfaceKind::BSpline);
  EXPECT_TRUE(s.is_planar());
}

TEST(OccPlanar, BSplineBumpedBeyondTheToleranceIsNotPlanar) {
  for (double bump : {1e-2, 1e-5}) {  // of a face 14 across; the tolerance is 1e-7 of that
    Handle(Geom_BSplineSurface) b = as_bspline(tilted_plane(), 5);
    const gp_Pnt p = b->Pole(1, 1);
    b->SetPole(1, 1, gp_Pnt(p.X(), p.Y(), p.Z() + bump));
    double u0, u1, v0, v1;
    b->Bounds(u0, u1, v0, v1);
    EXPECT_FALSE(surface_of(b, u0, u1, v0, v1).is_planar()) << "bump " << bump;
  }
}

TEST(OccPlanar, CylinderIsNotPlanarEvenWhenNearlyFlat) {
  // A strip of a radius-1000 cylinder 10 wide: sagitta 0.0125.
  const Handle(Geom_CylindricalSurface) c = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 1000.0);
  EXPECT_FALSE(surface_of(c, 0, 0.01, 0, 10).is_planar());
}

}  // namespace
}  // namespace semimesh::occ
