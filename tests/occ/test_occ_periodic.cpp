// Periodic faces, seams, poles and exact areas of the occ backend on OCC's own primitives, against
// closed forms (sphere 4 pi R^2, cylinder 2 pi R h) and the generic quadrature.
#include "semimesh/cad/trimmed_area.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::occ {
namespace {

int count_seams(const cad::Model& m) {
  int seams = 0;
  for (int s = 0; s < m.num_surfaces(); ++s)
    for (int c = 0; c < m.num_curves(); ++c) seams += m.is_seam(s, c) ? 1 : 0;
  return seams;
}

int count_poles(const cad::Model& m) {
  int poles = 0;
  for (int c = 0; c < m.num_curves(); ++c) poles += m.curve(c).is_degenerate() ? 1 : 0;
  return poles;
}

TEST(OccPeriodic, SphereHasASeamTwoPolesAndItsExactArea) {
  const double r = 1.5;
  auto m = model_from_shape(BRepPrimAPI_MakeSphere(r).Shape(), "occ");
  ASSERT_EQ(m->num_surfaces(), 1);
  const cad::Surface& sphere = m->surface(0);
  ASSERT_TRUE(sphere.period(0).has_value());
  EXPECT_NEAR(*sphere.period(0), 2 * M_PI, 1e-12);
  EXPECT_FALSE(sphere.period(1).has_value());
  EXPECT_EQ(count_seams(*m), 1);
  EXPECT_EQ(count_poles(*m), 2);
  EXPECT_TRUE(m->is_closed()) << "the poles are points: the seam alone closes the sphere";
  const cad::TrimmedArea area = cad::face_area(sphere);
  EXPECT_TRUE(area.exact);
  EXPECT_NEAR(area.area, 4 * M_PI * r * r, 1e-9 * r * r);
}

TEST(OccPeriodic, CylinderExactAreasAgreeWithClosedFormAndQuadrature) {
  const double r = 2.0, h = 3.0;
  auto m = model_from_shape(BRepPrimAPI_MakeCylinder(r, h).Shape(), "occ");
  EXPECT_EQ(count_seams(*m), 1);
  EXPECT_EQ(count_poles(*m), 0);
  double total = 0.0;
  for (int s = 0; s < m->num_surfaces(); ++s) {
    const cad::Surface& face = m->surface(s);
    const cad::TrimmedArea exact = cad::face_area(face);
    ASSERT_TRUE(exact.exact) << face.name();
    const cad::TrimmedArea quadrature = cad::trimmed_area(face, 1e-7);
    EXPECT_NEAR(exact.area, quadrature.area, 10 * quadrature.error_estimate + 1e-9) << face.name();
    if (face.kind() == cad::SurfaceKind::Cylinder) {
      EXPECT_NEAR(exact.area, 2 * M_PI * r * h, 1e-9 * r * h);
      EXPECT_NEAR(*face.period(0), 2 * M_PI, 1e-12);
    } else {
      EXPECT_NEAR(exact.area, M_PI * r * r, 1e-9 * r * r) << face.name();
    }
    total += exact.area;
  }
  EXPECT_NEAR(total, 2 * M_PI * r * h + 2 * M_PI * r * r, 1e-8);
}

}  // namespace
}  // namespace semimesh::occ
