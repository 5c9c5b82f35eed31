#include "sampling.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace conformance {

using semimesh::cad::Surface;

std::vector<Vec2> inside_samples(const Surface& surface, int n, double margin, double offset) {
  const auto box = surface.bounds();
  const double du = margin * box[0].length(), dv = margin * box[1].length();
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Vec2 uv(box[0].lo + box[0].length() * (i + offset) / n, box[1].lo + box[1].length() * (j + offset) / n);
      bool keep = surface.contains(uv);
      for (Vec2 d : {Vec2(du, 0), Vec2(-du, 0), Vec2(0, dv), Vec2(0, -dv)}) keep = keep && surface.contains(uv + d);
      if (keep) out.push_back(uv);
    }
  return out;
}

Vec2 central_sample(const Surface& surface) {
  const auto box = surface.bounds();
  const Vec2 centre(0.5 * (box[0].lo + box[0].hi), 0.5 * (box[1].lo + box[1].hi));
  const Vec2 size(box[0].length(), box[1].length());
  auto samples = inside_samples(surface, 15);
  if (samples.empty()) samples = inside_samples(surface, 61, 0.004);
  if (samples.empty()) throw std::runtime_error("surface '" + surface.name() + "' has no inside sample");
  Vec2 best = samples.front();
  for (const Vec2& s : samples)
    if ((s - centre).cwiseQuotient(size).norm() < (best - centre).cwiseQuotient(size).norm()) best = s;
  return best;
}

namespace {

// 3-point Gauss-Legendre on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr std::array<double, 3> kNodes = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> kWeights = {0.5555555555555556, 0.8888888888888888, 0.5555555555555556};
constexpr double kPi = 3.14159265358979323846;

struct Cell {
  double u0, u1, v0, v1;
  int level;
};

// Solid angle of one face seen from q (signed by the fluid normal).
double solid_angle(const Surface& s, const Vec3& q) {
  const auto box = s.bounds();
  constexpr int kBase = 8, kMaxLevel = 16;
  constexpr size_t kMaxCells = 400000;
  std::vector<Cell> pending;  // cells still to test or split
  for (int i = 0; i < kBase; ++i)
    for (int j = 0; j < kBase; ++j)
      pending.push_back(Cell{box[0].lo + box[0].length() * i / kBase, box[0].lo + box[0].length() * (i + 1) / kBase,
                          box[1].lo + box[1].length() * j / kBase, box[1].lo + box[1].length() * (j + 1) / kBase, 0});
  double sum = 0.0;
  size_t visited = 0;
  while (!pending.empty()) {
    Cell c = pending.back();
    pending.pop_back();
    if (++visited > kMaxCells) throw std::runtime_error("winding number: too many cells on surface '" + s.name() + "'");
    const double hu = 0.5 * (c.u1 - c.u0), hv = 0.5 * (c.v1 - c.v0);
    const auto mid = s.derivatives(Vec2(c.u0 + hu, c.v0 + hv));
    const double size = 2.0 * (hu * mid.du.norm() + hv * mid.dv.norm());
    const double distance = (mid.p - q).norm();
    bool inside_any = false, outside_any = false;
    double cell = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Vec2 uv(c.u0 + hu * (1 + kNodes[i]), c.v0 + hv * (1 + kNodes[j]));
        if (!s.contains(uv)) {
          outside_any = true;
          continue;
        }
        inside_any = true;
        auto d = s.derivatives(uv);
        Vec3 r = d.p - q;
        double r3 = std::pow(r.norm(), 3);
        cell += kWeights[i] * kWeights[j] * s.orientation() * r.dot(d.du.cross(d.dv)) / r3;
      }
    // Past the first levels a cell with no inside point is taken as outside the face.
    if (!inside_any && c.level >= 2) continue;
    // Cells cut by a trim curve must be finer: only their inside Gauss points count.
    const double ratio = (inside_any && outside_any) ? 0.1 : 0.5;
    if (c.level < kMaxLevel && size > ratio * distance) {
      const double um = c.u0 + hu, vm = c.v0 + hv;
      const int l = c.level + 1;
      pending.push_back(Cell{c.u0, um, c.v0, vm, l});
      pending.push_back(Cell{um, c.u1, c.v0, vm, l});
      pending.push_back(Cell{c.u0, um, vm, c.v1, l});
      pending.push_back(Cell{um, c.u1, vm, c.v1, l});
    } else {
      sum += cell * hu * hv;
    }
  }
  return sum;
}

}  // namespace

double winding_number(const semimesh::cad::Model& model, const Vec3& q) {
  double total = 0.0;
  for (int s = 0; s < model.num_surfaces(); ++s) total += solid_angle(model.surface(s), q);
  return total / (4.0 * kPi);
}

double simpson_length(const semimesh::cad::Curve& curve, double a, double b, int intervals) {
  const double h = (b - a) / intervals;
  double sum = curve.derivatives(a).d1.norm() + curve.derivatives(b).d1.norm();
  for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4.0 : 2.0) * curve.derivatives(a + k * h).d1.norm();
  return sum * h / 3.0;
}

}  // namespace conformance
