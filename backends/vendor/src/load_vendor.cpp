// Builds a cad::Model from a vendor model: enumerate, translate ids and conventions, finalize.
#include "semimesh/vendor/vendor_backend.hpp"

#include "connection.hpp"
#include "vendor_curve.hpp"
#include "vendor_surface.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <unordered_map>

namespace semimesh::vendor {
namespace {

using Kind = cad::CadError::Kind;

// Source params -> the kernel's "key=value;key=value" option string.
std::string option_string(const cad::Params& params) {
  std::string out;
  for (const auto& [key, value] : params.all()) {
    if (key.empty() || key.find_first_of("=;") != std::string::npos || value.find(';') != std::string::npos)
      throw cad::CadError(Kind::BadParameter, "vendor CAD: load option '" + key + "' = '" + value +
                                                  "': keys must be non-empty without '=' or ';', values without ';'");
    out += (out.empty() ? "" : ";") + key + "=" + value;
  }
  return out;
}

std::string unit_name(vc_unit unit) {
  switch (unit) {
    case VC_UNIT_METRE: return "m";
    case VC_UNIT_MILLIMETRE: return "mm";
    case VC_UNIT_CENTIMETRE: return "cm";
    case VC_UNIT_INCH: return "in";
    case VC_UNIT_FOOT: return "ft";
    default: return "unknown";
  }
}

cad::SurfaceKind surface_kind(vc_geometry_type type) {
  switch (type) {
    case VC_GEOM_PLANE: return cad::SurfaceKind::Plane;
    case VC_GEOM_CYLINDER: return cad::SurfaceKind::Cylinder;
    case VC_GEOM_NURBS_SURFACE: return cad::SurfaceKind::BSpline;
    case VC_GEOM_ANALYTIC_SURFACE: return cad::SurfaceKind::Analytic;
    default: return cad::SurfaceKind::Other;
  }
}

cad::CurveKind curve_kind(vc_geometry_type type) {
  switch (type) {
    case VC_GEOM_LINE: return cad::CurveKind::Line;
    case VC_GEOM_CIRCLE: return cad::CurveKind::Circle;
    case VC_GEOM_NURBS_CURVE: return cad::CurveKind::BSpline;
    case VC_GEOM_ANALYTIC_CURVE: return cad::CurveKind::Analytic;
    default: return cad::CurveKind::Other;
  }
}

// Reads entities in the kernel's enumeration order and gives them dense 0-based ids.
class Builder {
 public:
  Builder(std::shared_ptr<Connection> connection, std::string path)
      : connection_(std::move(connection)), path_(std::move(path)), model_(std::make_unique<cad::Model>("vendor")) {}

  std::unique_ptr<cad::Model> build() {
    read_model_properties();
    read_vertices();
    read_edges();
    read_face_senses();
    read_faces();
    model_->set_thread_safe(true);  // Connection::call serialises every kernel call
    model_->keep_alive(connection_);
    model_->finalize();
    return std::move(model_);
  }

 private:
  EntityRef model_ref() const { return {"model", VC_NULL_ENTITY, -1, &path_}; }

  std::vector<vc_entity> list(vc_entity_type type) const {
    int count = 0;
    connection_->call("vc_model_entity_count", model_ref(),
                      [&](vc_model m) { return vc_model_entity_count(m, type, &count); });
    std::vector<vc_entity> out(static_cast<size_t>(std::max(count, 0)));
    for (int k = 0; k < count; ++k)
      connection_->call("vc_model_entity", model_ref(),
                        [&](vc_model m) { return vc_model_entity(m, type, k + 1, &out[k]); });
    return out;
  }

  std::string name_of(vc_entity entity, const char* type_name) const {
    const char* name = nullptr;
    connection_->call("vc_entity_name", {type_name, entity, -1, nullptr},
                      [&](vc_model m) { return vc_entity_name(m, entity, &name); });
    return name ? name : "";
  }

  // Vendor id -> semimesh id, or a CadError naming the dangling reference.
  static int lookup(const std::unordered_map<vc_entity, int>& ids, vc_entity entity, const char* what,
                    const EntityRef& from) {
    auto it = ids.find(entity);
    if (it == ids.end())
      throw cad::CadError(Kind::Geometry, "vendor CAD: " + describe(from) + " refers to " + what + " #" +
                                              std::to_string(entity) + ", which the model does not list");
    return it->second;
  }

  void read_model_properties() {
    vc_unit unit = VC_UNIT_UNKNOWN;
    double tolerance = 0.0;
    connection_->call("vc_model_units", model_ref(), [&](vc_model m) { return vc_model_units(m, &unit); });
    connection_->call("vc_model_tolerance", model_ref(), [&](vc_model m) { return vc_model_tolerance(m, &tolerance); });
    model_->set_units(unit_name(unit), 1.0);
    model_->set_units_origin("declared by the vendor kernel's model");
    model_->set_tolerance(tolerance);
  }

  void read_vertices() {
    for (vc_entity v : list(VC_TYPE_VERTEX)) {
      std::string name = name_of(v, "vertex");
      cad::Vec3 p;
      connection_->call("vc_vertex_point", {"vertex", v, model_->num_vertices(), &name},
                        [&](vc_model m) { return vc_vertex_point(m, v, p.data()); });
      vertex_ids_[v] = model_->add_vertex(p, std::move(name));
    }
  }

  void read_edges() {
    for (vc_entity e : list(VC_TYPE_EDGE)) {
      std::string name = name_of(e, "edge");
      const EntityRef ref{"edge", e, model_->num_curves(), &name};
      cad::Interval range;
      vc_geometry_type type = VC_GEOM_OTHER;
      vc_entity start = VC_NULL_ENTITY, end = VC_NULL_ENTITY;
      connection_->call("vc_edge_range", ref, [&](vc_model m) { return vc_edge_range(m, e, &range.lo, &range.hi); });
      connection_->call("vc_edge_geometry", ref, [&](vc_model m) { return vc_edge_geometry(m, e, &type); });
      connection_->call("vc_edge_vertices", ref, [&](vc_model m) { return vc_edge_vertices(m, e, &start, &end); });
      int degenerate = 0;
      connection_->call("vc_edge_degenerate", ref, [&](vc_model m) { return vc_edge_degenerate(m, e, &degenerate); });
      int first = lookup(vertex_ids_, start, "vertex", ref), last = lookup(vertex_ids_, end, "vertex", ref);
      int id = model_->num_curves();
      edge_ids_[e] = id;
      model_->add_curve(std::make_unique<VendorCurve>(id, std::move(name), connection_, e, curve_kind(type), range,
                                                      degenerate != 0),
                        first, last);
    }
  }

  // A face's sense comes from the bodies it bounds; a face outside every body keeps its natural
  // normal. Bodies that disagree about one face make the fluid side ambiguous: refuse.
  void read_face_senses() {
    for (vc_entity body : list(VC_TYPE_BODY)) {
      const EntityRef ref{"body", body, -1, nullptr};
      int count = 0;
      connection_->call("vc_body_face_count", ref, [&](vc_model m) { return vc_body_face_count(m, body, &count); });
      for (int k = 1; k <= count; ++k) {
        vc_entity face = VC_NULL_ENTITY;
        vc_sense sense = VC_SENSE_SAME;
        connection_->call("vc_body_face", ref, [&](vc_model m) { return vc_body_face(m, body, k, &face, &sense); });
        auto [it, inserted] = face_senses_.emplace(face, sense);
        if (!inserted && it->second != sense)
          throw cad::CadError(Kind::Geometry, "vendor CAD: face #" + std::to_string(face) +
                                                  " has opposite senses in two bodies (the second is body #" +
                                                  std::to_string(body) + "); cannot tell which side is fluid");
      }
    }
  }

  void read_faces() {
    for (vc_entity f : list(VC_TYPE_FACE)) {
      std::string name = name_of(f, "face");
      const EntityRef ref{"face", f, model_->num_surfaces(), &name};
      std::array<cad::Interval, 2> box;
      double lo[2], hi[2];
      vc_geometry_type type = VC_GEOM_OTHER;
      connection_->call("vc_face_range", ref, [&](vc_model m) { return vc_face_range(m, f, lo, hi); });
      connection_->call("vc_face_geometry", ref, [&](vc_model m) { return vc_face_geometry(m, f, &type); });
      box[0] = {lo[0], hi[0]};
      box[1] = {lo[1], hi[1]};
      int periodic[2] = {0, 0};
      double period[2] = {0.0, 0.0};
      connection_->call("vc_face_periodicity", ref, [&](vc_model m) { return vc_face_periodicity(m, f, periodic, period); });
      std::array<std::optional<double>, 2> periods;
      for (int i = 0; i < 2; ++i)
        if (periodic[i]) periods[i] = period[i];
      auto sense = face_senses_.find(f);
      const bool reversed = sense != face_senses_.end() && sense->second == VC_SENSE_REVERSED;
      std::vector<cad::Loop> loops = read_loops(f, ref, reversed);
      int id = model_->num_surfaces();
      model_->add_surface(std::make_unique<VendorSurface>(id, std::move(name), reversed ? -1 : +1, connection_, f,
                                                          surface_kind(type), box, periods),
                          std::move(loops));
    }
  }

  // Vendor loops run counter-clockwise around the natural normal; ours around the fluid normal.
  // On a reversed face the two differ: walk each loop backwards, every edge the other way.
  std::vector<cad::Loop> read_loops(vc_entity f, const EntityRef& ref, bool reversed) const {
    int loop_count = 0;
    connection_->call("vc_face_loop_count", ref, [&](vc_model m) { return vc_face_loop_count(m, f, &loop_count); });
    std::vector<cad::Loop> loops(static_cast<size_t>(std::max(loop_count, 0)));
    for (int l = 1; l <= loop_count; ++l) {
      int size = 0;
      connection_->call("vc_face_loop_size", ref, [&](vc_model m) { return vc_face_loop_size(m, f, l, &size); });
      cad::Loop& loop = loops[l - 1];
      for (int k = 1; k <= size; ++k) {
        vc_entity edge = VC_NULL_ENTITY;
        vc_sense sense = VC_SENSE_SAME;
        connection_->call("vc_face_loop_edge", ref,
                          [&](vc_model m) { return vc_face_loop_edge(m, f, l, k, &edge, &sense); });
        bool forward = (sense == VC_SENSE_SAME) != reversed;
        loop.uses.push_back(cad::CurveUse{lookup(edge_ids_, edge, "edge", ref), forward});
      }
      if (reversed) std::reverse(loop.uses.begin(), loop.uses.end());
    }
    return loops;
  }

  std::shared_ptr<Connection> connection_;
  std::string path_;
  std::unique_ptr<cad::Model> model_;
  std::unordered_map<vc_entity, int> vertex_ids_, edge_ids_;
  std::unordered_map<vc_entity, vc_sense> face_senses_;
};

}  // namespace

std::unique_ptr<cad::Model> load_vendor(const cad::Source& source) {
  if (source.path.empty())
    throw cad::CadError(Kind::BadParameter,
                        "backend 'vendor' needs a model path (a file the vendor kernel reads, e.g. wing.vcad)");
  auto connection = std::make_shared<Connection>(source.path, option_string(source.params));
  return Builder(std::move(connection), source.path).build();
}

cad::BackendInfo backend_info() {
  return cad::BackendInfo{"vendor",
                          "proprietary CAD kernel through its C API (CADfix CFI style); needs the vendor SDK",
                          {".vcad"},
                          load_vendor,
                          {}};
}

}  // namespace semimesh::vendor
