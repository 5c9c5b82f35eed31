#include "timed_model.hpp"

#include <chrono>

namespace semimesh::bench {
namespace {

class Stopwatch {
 public:
  explicit Stopwatch(CadClock& clock) : clock_(clock), start_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() {
    clock_.nanoseconds += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_)
                              .count();
    ++clock_.calls;
  }

 private:
  CadClock& clock_;
  std::chrono::steady_clock::time_point start_;
};

class TimedCurve : public cad::Curve {
 public:
  TimedCurve(const cad::Curve& inner, CadClock& clock) : Curve(inner.id(), inner.name()), inner_(inner), clock_(clock) {}
  cad::CurveKind kind() const override { return inner_.kind(); }
  cad::Interval bounds() const override { return inner_.bounds(); }
  cad::CurveDerivatives derivatives(double t) const override {
    Stopwatch w(clock_);
    return inner_.derivatives(t);
  }
  cad::Vec3 point(double t) const override {
    Stopwatch w(clock_);
    return inner_.point(t);
  }
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess) const override {
    Stopwatch w(clock_);
    return inner_.project(x, guess);
  }
  double arc_length(double a, double b) const override {
    Stopwatch w(clock_);
    return inner_.arc_length(a, b);
  }
  double parameter_at_length(double t_start, double s) const override {
    Stopwatch w(clock_);
    return inner_.parameter_at_length(t_start, s);
  }

 private:
  const cad::Curve& inner_;
  CadClock& clock_;
};

class TimedSurface : public cad::Surface {
 public:
  TimedSurface(const cad::Surface& inner, CadClock& clock)
      : Surface(inner.id(), inner.name(), inner.orientation()), inner_(inner), clock_(clock) {}
  cad::SurfaceKind kind() const override { return inner_.kind(); }
  std::array<cad::Interval, 2> bounds() const override { return inner_.bounds(); }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    Stopwatch w(clock_);
    return inner_.derivatives(uv);
  }
  cad::Vec3 point(const cad::Vec2& uv) const override {
    Stopwatch w(clock_);
    return inner_.point(uv);
  }
  bool is_planar() const override { return inner_.is_planar(); }
  bool contains(const cad::Vec2& uv) const override {
    Stopwatch w(clock_);
    return inner_.contains(uv);
  }
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<cad::Vec2> guess) const override {
    Stopwatch w(clock_);
    return inner_.project(x, guess);
  }

 private:
  const cad::Surface& inner_;
  CadClock& clock_;
};

}  // namespace

std::unique_ptr<cad::Model> timed_model(const cad::Model& inner, CadClock& clock) {
  auto model = std::make_unique<cad::Model>(inner.backend());
  for (int v = 0; v < inner.num_vertices(); ++v) model->add_vertex(inner.vertex(v).point, inner.vertex(v).name);
  for (int c = 0; c < inner.num_curves(); ++c) {
    const auto ends = inner.curve_vertices(c);
    model->add_curve(std::make_unique<TimedCurve>(inner.curve(c), clock), ends[0], ends[1]);
  }
  for (int s = 0; s < inner.num_surfaces(); ++s)
    model->add_surface(std::make_unique<TimedSurface>(inner.surface(s), clock), inner.loops(s));
  model->set_units(inner.units(), inner.scale_applied());
  model->set_tolerance(inner.tolerance());
  model->set_thread_safe(inner.thread_safe());
  model->finalize();
  return model;
}

}  // namespace semimesh::bench
