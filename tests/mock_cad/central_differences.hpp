// The analytic backend's derivatives against central differences of its own values: first
// derivatives to 1e-8, second to 1e-6 (relative to the vector's size, at least 1), enough to catch
// a wrong sign or a missing chain-rule term, which are off by O(1).
#pragma once

#include "semimesh/cad/surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace naca_test {

inline void expect_close(const semimesh::cad::Vec3& exact, const semimesh::cad::Vec3& fd, double tol,
                         const std::string& what) {
  EXPECT_LT((exact - fd).norm(), tol * std::max(1.0, exact.norm())) << what << "\n exact " << exact.transpose()
                                                                   << "\n fd    " << fd.transpose();
}

/// S, its first and second derivatives at uv against central differences with steps hu, hv.
inline void expect_surface_derivatives_match_differences(const semimesh::cad::Surface& surf,
                                                         const semimesh::cad::Vec2& uv, double hu, double hv,
                                                         const std::string& at) {
  using semimesh::cad::Vec2;
  const auto d = surf.derivatives(uv);
  const auto pu = surf.derivatives(uv + Vec2(hu, 0)), mu = surf.derivatives(uv - Vec2(hu, 0));
  const auto pv = surf.derivatives(uv + Vec2(0, hv)), mv = surf.derivatives(uv - Vec2(0, hv));
  EXPECT_LT((d.p - surf.point(uv)).norm(), 1e-15) << at;
  expect_close(d.du, (pu.p - mu.p) / (2 * hu), 1e-8, "du " + at);
  expect_close(d.dv, (pv.p - mv.p) / (2 * hv), 1e-8, "dv " + at);
  expect_close(d.duu, (pu.du - mu.du) / (2 * hu), 1e-6, "duu " + at);
  expect_close(d.duv, (pv.du - mv.du) / (2 * hv), 1e-6, "duv " + at);
  expect_close(d.duv, (pu.dv - mu.dv) / (2 * hu), 1e-6, "dvu " + at);
  expect_close(d.dvv, (pv.dv - mv.dv) / (2 * hv), 1e-6, "dvv " + at);
}

}  // namespace naca_test
