#include "naca_reference.hpp"

#include <cmath>
#include <stdexcept>

namespace naca_test {

double half_thickness(double t, double x, bool sharp) {
  const double a4 = sharp ? -0.1036 : -0.1015;
  return 5.0 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x + a4 * x * x * x * x);
}

namespace {
double camber_slope(double m, double p, double x) {
  if (m == 0.0) return 0.0;
  return x < p ? 2.0 * m / (p * p) * (p - x) : 2.0 * m / ((1 - p) * (1 - p)) * (p - x);
}
}  // namespace

double camber(double m, double p, double x) {
  if (m == 0.0) return 0.0;
  return x < p ? m / (p * p) * (2 * p * x - x * x) : m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
}

Point2 surface_point(double m, double p, double t, double x, bool upper, bool sharp) {
  const double theta = std::atan(camber_slope(m, p, x));
  const double yt = half_thickness(t, x, sharp), yc = camber(m, p, x);
  const double s = upper ? 1.0 : -1.0;
  return Point2{x - s * yt * std::sin(theta), yc + s * yt * std::cos(theta)};
}

std::unique_ptr<semimesh::cad::Model> wing(const semimesh::mock_cad::NacaWingParams& params) {
  return semimesh::mock_cad::make_naca_wing(params);
}

int surface_id(const semimesh::cad::Model& model, const std::string& name) {
  auto id = model.find_surface(name);
  if (!id) throw std::runtime_error("no surface named " + name);
  return *id;
}

int curve_id(const semimesh::cad::Model& model, const std::string& name) {
  for (int c = 0; c < model.num_curves(); ++c)
    if (model.curve(c).name() == name) return c;
  throw std::runtime_error("no curve named " + name);
}

}  // namespace naca_test
