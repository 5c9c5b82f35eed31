// Shared helpers of the occ tests: test data paths and sampling of trimmed faces.
#pragma once

#include "semimesh/cad/model.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace semimesh::occ::test {

inline std::string testdata(const std::string& name) { return std::string(SEMIMESH_TESTDATA_DIR) + "/cad/" + name; }

inline bool exists(const std::string& path) { return std::ifstream(path).good(); }

/// Parameters on an n x n grid over the surface's box that lie inside the trimmed face,
/// kept a little away from the box edges.
inline std::vector<cad::Vec2> inside_samples(const cad::Surface& s, int n = 9) {
  std::vector<cad::Vec2> out;
  const auto box = s.bounds();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      cad::Vec2 uv(box[0].lo + box[0].length() * (i + 0.5) / n, box[1].lo + box[1].length() * (j + 0.5) / n);
      if (s.contains(uv)) out.push_back(uv);
    }
  return out;
}

/// Integral of x.n dA over all surfaces with the fluid normal n (midpoint rule on the inside
/// samples). By the divergence theorem it is +3 V when the normals point out of the bounded
/// region (a solid body), -3 V when they point into it (fluid inside a box); tests use its sign.
inline double position_flux(const cad::Model& model, int n = 40) {
  double flux = 0.0;
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const cad::Surface& surface = model.surface(s);
    const auto box = surface.bounds();
    const double cell = box[0].length() * box[1].length() / (n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        cad::Vec2 uv(box[0].lo + box[0].length() * (i + 0.5) / n, box[1].lo + box[1].length() * (j + 0.5) / n);
        if (!surface.contains(uv)) continue;
        cad::SurfaceDerivatives d = surface.derivatives(uv);
        flux += d.p.dot(surface.normal(uv)) * d.du.cross(d.dv).norm() * cell;
      }
  }
  return flux;
}

}  // namespace semimesh::occ::test
