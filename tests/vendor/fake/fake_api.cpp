// The C entry points of the fake kernel (vendor_cad_api.h) over the analytic NACA model.
// Handles are checked against the live sets so a stale or foreign handle is VC_ERR_BAD_HANDLE,
// not undefined behaviour, as a defensive vendor library would do.
#include "vendor_cad_api.h"

#include "fake_model.hpp"
#include "load_request.hpp"

#include "semimesh/cad/error.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

using semimesh::vendor_fake::EdgeUse;
using semimesh::vendor_fake::FakeError;
using semimesh::vendor_fake::FakeModel;
namespace cad = semimesh::cad;

struct vc_session_s {
  std::string last_error;
  std::vector<vc_model> models;
};

struct vc_model_s {
  vc_session session;
  FakeModel kernel;
};

namespace {

std::mutex g_handles_mutex;
std::set<const vc_session_s*> g_sessions;
std::set<const vc_model_s*> g_models;
// Message of the last call on this thread that had no valid handle to attach it to.
thread_local std::string g_orphan_error;

bool live(vc_session session) {
  std::lock_guard<std::mutex> lock(g_handles_mutex);
  return session && g_sessions.count(session);
}

bool live(vc_model model) {
  std::lock_guard<std::mutex> lock(g_handles_mutex);
  return model && g_models.count(model);
}

vc_status fail_orphan(vc_status status, std::string message) {
  g_orphan_error = std::move(message);
  return status;
}

// Runs `body`, turning exceptions into a status and the session's message.
template <class Body>
vc_status guarded(vc_session session, Body&& body) {
  try {
    body();
    return VC_OK;
  } catch (const FakeError& e) {
    session->last_error = e.message;
    return e.status;
  } catch (const std::exception& e) {
    session->last_error = std::string("internal error: ") + e.what();
    return VC_ERR_INTERNAL;
  }
}

// Runs `body(kernel)` on a live model.
template <class Body>
vc_status on_model(vc_model model, Body&& body) {
  if (!live(model)) return fail_orphan(VC_ERR_BAD_HANDLE, "model handle is NULL, freed or not from this library");
  return guarded(model->session, [&] { body(model->kernel); });
}

template <class T>
void require(const T* out, const char* what) {
  if (!out) throw FakeError{VC_ERR_BAD_PARAM, std::string(what) + " is NULL"};
}

void store(double out[3], const cad::Vec3& v) {
  if (out) for (int k = 0; k < 3; ++k) out[k] = v[k];
}

// A parameter may stray outside its range by 1e-6 of the range (rounding), no further.
void check_parameter(double value, const cad::Interval& range, const char* name, vc_entity entity) {
  if (std::isnan(value)) throw FakeError{VC_ERR_BAD_PARAM, std::string(name) + " is NaN"};
  double slack = 1e-6 * range.length();
  if (!range.contains(value, slack))
    throw FakeError{VC_ERR_OUT_OF_RANGE, std::string(name) + " = " + std::to_string(value) + " outside [" +
                                             std::to_string(range.lo) + ", " + std::to_string(range.hi) +
                                             "] of entity " + std::to_string(entity)};
}

void check_uv(const double uv[2], const cad::Surface& surface, vc_entity face) {
  require(uv, "uv");
  auto box = surface.bounds();
  check_parameter(uv[0], box[0], "u", face);
  check_parameter(uv[1], box[1], "v", face);
}

vc_geometry_type geometry_of(const cad::Surface& surface) {
  switch (surface.kind()) {
    case cad::SurfaceKind::Plane: return VC_GEOM_PLANE;
    case cad::SurfaceKind::Cylinder: return VC_GEOM_CYLINDER;
    case cad::SurfaceKind::BSpline: return VC_GEOM_NURBS_SURFACE;
    case cad::SurfaceKind::Analytic: return VC_GEOM_ANALYTIC_SURFACE;
    default: return VC_GEOM_OTHER;
  }
}

vc_geometry_type geometry_of(const cad::Curve& curve) {
  switch (curve.kind()) {
    case cad::CurveKind::Line: return VC_GEOM_LINE;
    case cad::CurveKind::Circle: return VC_GEOM_CIRCLE;
    case cad::CurveKind::BSpline: return VC_GEOM_NURBS_CURVE;
    case cad::CurveKind::Analytic: return VC_GEOM_ANALYTIC_CURVE;
    default: return VC_GEOM_OTHER;
  }
}

vc_unit unit_of(const std::string& name) {
  if (name == "m") return VC_UNIT_METRE;
  if (name == "mm") return VC_UNIT_MILLIMETRE;
  if (name == "cm") return VC_UNIT_CENTIMETRE;
  if (name == "in") return VC_UNIT_INCH;
  if (name == "ft") return VC_UNIT_FOOT;
  return VC_UNIT_UNKNOWN;
}

// The loop-th (1-based) loop of a face.
const std::vector<EdgeUse>& loop_of(const FakeModel& k, vc_entity face, int loop) {
  const auto& loops = k.loops(k.index_of(face, VC_TYPE_FACE));
  if (loop < 1 || loop > static_cast<int>(loops.size()))
    throw FakeError{VC_ERR_OUT_OF_RANGE, "loop " + std::to_string(loop) + " outside 1.." + std::to_string(loops.size()) +
                                             " of face " + std::to_string(face)};
  return loops[loop - 1];
}

// Generator parameters the mock rejects: a bad file when they came from one, else a bad parameter.
std::unique_ptr<cad::Model> generate(const semimesh::vendor_fake::LoadRequest& request) {
  try {
    return semimesh::mock_cad::load_naca(cad::Source{"", request.naca});
  } catch (const cad::CadError& e) {
    throw FakeError{request.from_file ? VC_ERR_BAD_FILE : VC_ERR_BAD_PARAM, e.what()};
  }
}

}  // namespace

extern "C" {

int vc_api_version(void) { return VC_API_VERSION; }

const char* vc_status_name(vc_status status) {
  switch (status) {
    case VC_OK: return "VC_OK";
    case VC_ERR_FILE_NOT_FOUND: return "VC_ERR_FILE_NOT_FOUND";
    case VC_ERR_BAD_FILE: return "VC_ERR_BAD_FILE";
    case VC_ERR_BAD_HANDLE: return "VC_ERR_BAD_HANDLE";
    case VC_ERR_BAD_PARAM: return "VC_ERR_BAD_PARAM";
    case VC_ERR_OUT_OF_RANGE: return "VC_ERR_OUT_OF_RANGE";
    case VC_ERR_UNKNOWN_OPTION: return "VC_ERR_UNKNOWN_OPTION";
    case VC_ERR_WRONG_TYPE: return "VC_ERR_WRONG_TYPE";
    case VC_ERR_EMPTY_MODEL: return "VC_ERR_EMPTY_MODEL";
    case VC_ERR_NOT_CONVERGED: return "VC_ERR_NOT_CONVERGED";
    case VC_ERR_INTERNAL: return "VC_ERR_INTERNAL";
    default: return "VC_UNKNOWN_STATUS";
  }
}

vc_status vc_session_open(vc_session* session) {
  if (!session) return fail_orphan(VC_ERR_BAD_PARAM, "session out-parameter is NULL");
  auto* created = new vc_session_s;
  std::lock_guard<std::mutex> lock(g_handles_mutex);
  g_sessions.insert(created);
  *session = created;
  return VC_OK;
}

vc_status vc_model_free(vc_model model) {
  if (!model) return VC_OK;
  if (!live(model)) return fail_orphan(VC_ERR_BAD_HANDLE, "model handle is freed or not from this library");
  auto& owned = model->session->models;
  owned.erase(std::remove(owned.begin(), owned.end(), model), owned.end());
  {
    std::lock_guard<std::mutex> lock(g_handles_mutex);
    g_models.erase(model);
  }
  delete model;
  return VC_OK;
}

vc_status vc_session_close(vc_session session) {
  if (!session) return VC_OK;
  if (!live(session)) return fail_orphan(VC_ERR_BAD_HANDLE, "session handle is closed or not from this library");
  while (!session->models.empty()) vc_model_free(session->models.back());
  {
    std::lock_guard<std::mutex> lock(g_handles_mutex);
    g_sessions.erase(session);
  }
  delete session;
  return VC_OK;
}

const char* vc_error_message(vc_session session) {
  if (!live(session)) return g_orphan_error.c_str();
  return session->last_error.c_str();
}

vc_status vc_model_load(vc_session session, const char* path, const char* options, vc_model* model) {
  if (!live(session)) return fail_orphan(VC_ERR_BAD_HANDLE, "session handle is NULL, closed or not from this library");
  return guarded(session, [&] {
    require(model, "model out-parameter");
    auto request = semimesh::vendor_fake::parse_load_request(path, options);
    std::unique_ptr<cad::Model> geometry = generate(request);
    if (geometry->num_surfaces() == 0) throw FakeError{VC_ERR_EMPTY_MODEL, std::string("'") + path + "' holds no faces"};
    vc_unit units = request.units.value_or(unit_of(geometry->units()));
    double tolerance = request.tolerance.value_or(geometry->tolerance());
    auto* loaded = new vc_model_s{session, FakeModel(std::move(geometry), units, tolerance)};
    session->models.push_back(loaded);
    std::lock_guard<std::mutex> lock(g_handles_mutex);
    g_models.insert(loaded);
    *model = loaded;
  });
}

vc_status vc_model_units(vc_model model, vc_unit* unit) {
  return on_model(model, [&](const FakeModel& k) {
    require(unit, "unit");
    *unit = k.units();
  });
}

vc_status vc_model_tolerance(vc_model model, double* tolerance) {
  return on_model(model, [&](const FakeModel& k) {
    require(tolerance, "tolerance");
    *tolerance = k.tolerance();
  });
}

vc_status vc_model_entity_count(vc_model model, vc_entity_type type, int* count) {
  return on_model(model, [&](const FakeModel& k) {
    require(count, "count");
    *count = k.count(type);
  });
}

vc_status vc_model_entity(vc_model model, vc_entity_type type, int index, vc_entity* entity) {
  return on_model(model, [&](const FakeModel& k) {
    require(entity, "entity");
    *entity = k.entity(type, index);
  });
}

vc_status vc_entity_get_type(vc_model model, vc_entity entity, vc_entity_type* type) {
  return on_model(model, [&](const FakeModel& k) {
    require(type, "type");
    *type = k.type_of(entity);
  });
}

vc_status vc_entity_name(vc_model model, vc_entity entity, const char** name) {
  return on_model(model, [&](const FakeModel& k) {
    require(name, "name");
    *name = k.name(entity).c_str();
  });
}

vc_status vc_body_face_count(vc_model model, vc_entity body, int* count) {
  return on_model(model, [&](const FakeModel& k) {
    require(count, "count");
    k.index_of(body, VC_TYPE_BODY);
    *count = k.count(VC_TYPE_FACE);  // the one body holds every face
  });
}

vc_status vc_body_face(vc_model model, vc_entity body, int index, vc_entity* face, vc_sense* sense) {
  return on_model(model, [&](const FakeModel& k) {
    require(face, "face");
    require(sense, "sense");
    k.index_of(body, VC_TYPE_BODY);
    vc_entity found = k.entity(VC_TYPE_FACE, index);
    *sense = k.reversed(k.index_of(found, VC_TYPE_FACE)) ? VC_SENSE_REVERSED : VC_SENSE_SAME;
    *face = found;
  });
}

vc_status vc_face_geometry(vc_model model, vc_entity face, vc_geometry_type* type) {
  return on_model(model, [&](const FakeModel& k) {
    require(type, "type");
    *type = geometry_of(k.geometry().surface(k.index_of(face, VC_TYPE_FACE)));
  });
}

vc_status vc_face_range(vc_model model, vc_entity face, double uv_min[2], double uv_max[2]) {
  return on_model(model, [&](const FakeModel& k) {
    require(uv_min, "uv_min");
    require(uv_max, "uv_max");
    auto box = k.geometry().surface(k.index_of(face, VC_TYPE_FACE)).bounds();
    uv_min[0] = box[0].lo;
    uv_min[1] = box[1].lo;
    uv_max[0] = box[0].hi;
    uv_max[1] = box[1].hi;
  });
}

vc_status vc_face_eval(vc_model model, vc_entity face, const double uv[2], double p[3], double du[3], double dv[3],
                       double duu[3], double duv[3], double dvv[3]) {
  return on_model(model, [&](const FakeModel& k) {
    const cad::Surface& s = k.geometry().surface(k.index_of(face, VC_TYPE_FACE));
    check_uv(uv, s, face);
    cad::SurfaceDerivatives d = s.derivatives(cad::Vec2(uv[0], uv[1]));
    store(p, d.p);
    store(du, d.du);
    store(dv, d.dv);
    store(duu, d.duu);
    store(duv, d.duv);
    store(dvv, d.dvv);
  });
}

vc_status vc_face_normal(vc_model model, vc_entity face, const double uv[2], double normal[3]) {
  return on_model(model, [&](const FakeModel& k) {
    require(normal, "normal");
    const cad::Surface& s = k.geometry().surface(k.index_of(face, VC_TYPE_FACE));
    check_uv(uv, s, face);
    cad::SurfaceDerivatives d = s.derivatives(cad::Vec2(uv[0], uv[1]));
    cad::Vec3 n = d.du.cross(d.dv);
    if (n.norm() == 0.0) throw FakeError{VC_ERR_INTERNAL, "degenerate point: du x dv vanishes"};
    store(normal, n.normalized());
  });
}

vc_status vc_face_periodicity(vc_model model, vc_entity face, int periodic[2], double period[2]) {
  return on_model(model, [&](const FakeModel& k) {
    require(periodic, "periodic");
    require(period, "period");
    const cad::Surface& s = k.geometry().surface(k.index_of(face, VC_TYPE_FACE));
    for (int i = 0; i < 2; ++i) {
      const std::optional<double> p = s.period(i);
      periodic[i] = p ? 1 : 0;
      period[i] = p.value_or(0.0);
    }
  });
}

vc_status vc_face_inside(vc_model model, vc_entity face, const double uv[2], int* inside) {
  return on_model(model, [&](const FakeModel& k) {
    require(uv, "uv");
    require(inside, "inside");
    *inside = k.geometry().surface(k.index_of(face, VC_TYPE_FACE)).contains(cad::Vec2(uv[0], uv[1])) ? 1 : 0;
  });
}

vc_status vc_face_project(vc_model model, vc_entity face, const double x[3], const double* uv_guess, double uv[2],
                          double p[3], double* distance, int* converged, int* inside) {
  return on_model(model, [&](const FakeModel& k) {
    require(x, "x");
    require(uv, "uv");
    const cad::Surface& s = k.geometry().surface(k.index_of(face, VC_TYPE_FACE));
    std::optional<cad::Vec2> guess;
    if (uv_guess) guess = cad::Vec2(uv_guess[0], uv_guess[1]);
    cad::SurfaceProjection r = s.project(cad::Vec3(x[0], x[1], x[2]), guess);
    uv[0] = r.uv[0];
    uv[1] = r.uv[1];
    store(p, r.point);
    if (distance) *distance = r.distance;
    if (converged) *converged = r.converged ? 1 : 0;
    if (inside) *inside = r.inside ? 1 : 0;
  });
}

vc_status vc_face_loop_count(vc_model model, vc_entity face, int* count) {
  return on_model(model, [&](const FakeModel& k) {
    require(count, "count");
    *count = static_cast<int>(k.loops(k.index_of(face, VC_TYPE_FACE)).size());
  });
}

vc_status vc_face_loop_size(vc_model model, vc_entity face, int loop, int* count) {
  return on_model(model, [&](const FakeModel& k) {
    require(count, "count");
    *count = static_cast<int>(loop_of(k, face, loop).size());
  });
}

vc_status vc_face_loop_edge(vc_model model, vc_entity face, int loop, int index, vc_entity* edge, vc_sense* sense) {
  return on_model(model, [&](const FakeModel& k) {
    require(edge, "edge");
    require(sense, "sense");
    const auto& uses = loop_of(k, face, loop);
    if (index < 1 || index > static_cast<int>(uses.size()))
      throw FakeError{VC_ERR_OUT_OF_RANGE, "edge use " + std::to_string(index) + " outside 1.." +
                                               std::to_string(uses.size()) + " of loop " + std::to_string(loop)};
    *edge = uses[index - 1].edge;
    *sense = uses[index - 1].sense;
  });
}

vc_status vc_edge_geometry(vc_model model, vc_entity edge, vc_geometry_type* type) {
  return on_model(model, [&](const FakeModel& k) {
    require(type, "type");
    *type = geometry_of(k.geometry().curve(k.index_of(edge, VC_TYPE_EDGE)));
  });
}

vc_status vc_edge_range(vc_model model, vc_entity edge, double* t0, double* t1) {
  return on_model(model, [&](const FakeModel& k) {
    require(t0, "t0");
    require(t1, "t1");
    cad::Interval range = k.geometry().curve(k.index_of(edge, VC_TYPE_EDGE)).bounds();
    *t0 = range.lo;
    *t1 = range.hi;
  });
}

vc_status vc_edge_degenerate(vc_model model, vc_entity edge, int* degenerate) {
  return on_model(model, [&](const FakeModel& k) {
    require(degenerate, "degenerate");
    *degenerate = k.geometry().curve(k.index_of(edge, VC_TYPE_EDGE)).is_degenerate() ? 1 : 0;
  });
}

vc_status vc_edge_eval(vc_model model, vc_entity edge, double t, double p[3], double d1[3], double d2[3]) {
  return on_model(model, [&](const FakeModel& k) {
    const cad::Curve& c = k.geometry().curve(k.index_of(edge, VC_TYPE_EDGE));
    check_parameter(t, c.bounds(), "t", edge);
    cad::CurveDerivatives d = c.derivatives(t);
    store(p, d.p);
    store(d1, d.d1);
    store(d2, d.d2);
  });
}

vc_status vc_edge_project(vc_model model, vc_entity edge, const double x[3], const double* t_guess, double* t,
                          double p[3], double* distance, int* converged) {
  return on_model(model, [&](const FakeModel& k) {
    require(x, "x");
    require(t, "t");
    const cad::Curve& c = k.geometry().curve(k.index_of(edge, VC_TYPE_EDGE));
    std::optional<double> guess;
    if (t_guess) guess = *t_guess;
    cad::CurveProjection r = c.project(cad::Vec3(x[0], x[1], x[2]), guess);
    *t = r.t;
    store(p, r.point);
    if (distance) *distance = r.distance;
    if (converged) *converged = r.converged ? 1 : 0;
  });
}

vc_status vc_edge_vertices(vc_model model, vc_entity edge, vc_entity* start, vc_entity* end) {
  return on_model(model, [&](const FakeModel& k) {
    require(start, "start");
    require(end, "end");
    auto ends = k.geometry().curve_vertices(k.index_of(edge, VC_TYPE_EDGE));
    *start = k.entity(VC_TYPE_VERTEX, ends[0] + 1);
    *end = k.entity(VC_TYPE_VERTEX, ends[1] + 1);
  });
}

vc_status vc_vertex_point(vc_model model, vc_entity vertex, double p[3]) {
  return on_model(model, [&](const FakeModel& k) {
    require(p, "p");
    store(p, k.geometry().vertex(k.index_of(vertex, VC_TYPE_VERTEX)).point);
  });
}

}  // extern "C"
