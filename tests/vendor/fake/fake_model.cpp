#include "fake_model.hpp"

#include <algorithm>

namespace semimesh::vendor_fake {
namespace {

const char* type_name(vc_entity_type type) {
  switch (type) {
    case VC_TYPE_BODY: return "body";
    case VC_TYPE_FACE: return "face";
    case VC_TYPE_EDGE: return "edge";
    case VC_TYPE_VERTEX: return "vertex";
  }
  return "entity";
}

}  // namespace

FakeModel::FakeModel(std::unique_ptr<cad::Model> geometry, vc_unit units, double tolerance)
    : geometry_(std::move(geometry)), units_(units), tolerance_(tolerance) {
  const cad::Model& g = *geometry_;
  entries_.push_back({VC_TYPE_BODY, 0, "body"});
  for (int s = 0; s < g.num_surfaces(); ++s) entries_.push_back({VC_TYPE_FACE, s, g.surface(s).name()});
  for (int c = 0; c < g.num_curves(); ++c) entries_.push_back({VC_TYPE_EDGE, c, g.curve(c).name()});
  for (int v = 0; v < g.num_vertices(); ++v) entries_.push_back({VC_TYPE_VERTEX, v, g.vertex(v).name});

  for (int s = 0; s < g.num_surfaces(); ++s) {
    const bool flip = g.surface(s).orientation() < 0;
    reversed_.push_back(flip);
    std::vector<std::vector<EdgeUse>> face_loops;
    for (const cad::Loop& loop : g.loops(s)) {
      std::vector<EdgeUse> uses;
      for (const cad::CurveUse& use : loop.uses) {
        // Around the natural normal a reversed face's loop runs the other way.
        bool same = use.forward != flip;
        uses.push_back({first_id(VC_TYPE_EDGE) + use.curve, same ? VC_SENSE_SAME : VC_SENSE_REVERSED});
      }
      if (flip) std::reverse(uses.begin(), uses.end());
      face_loops.push_back(std::move(uses));
    }
    loops_.push_back(std::move(face_loops));
  }
}

vc_entity FakeModel::first_id(vc_entity_type type) const {
  const cad::Model& g = *geometry_;
  switch (type) {
    case VC_TYPE_BODY: return 1;
    case VC_TYPE_FACE: return 2;
    case VC_TYPE_EDGE: return 2 + g.num_surfaces();
    case VC_TYPE_VERTEX: return 2 + g.num_surfaces() + g.num_curves();
  }
  throw FakeError{VC_ERR_BAD_PARAM, "entity type " + std::to_string(static_cast<int>(type)) + " does not exist"};
}

int FakeModel::count(vc_entity_type type) const {
  const cad::Model& g = *geometry_;
  switch (type) {
    case VC_TYPE_BODY: return 1;
    case VC_TYPE_FACE: return g.num_surfaces();
    case VC_TYPE_EDGE: return g.num_curves();
    case VC_TYPE_VERTEX: return g.num_vertices();
  }
  throw FakeError{VC_ERR_BAD_PARAM, "entity type " + std::to_string(static_cast<int>(type)) + " does not exist"};
}

vc_entity FakeModel::entity(vc_entity_type type, int index) const {
  int n = count(type);
  if (index < 1 || index > n)
    throw FakeError{VC_ERR_OUT_OF_RANGE, std::string(type_name(type)) + " index " + std::to_string(index) +
                                             " outside 1.." + std::to_string(n)};
  return first_id(type) + index - 1;
}

vc_entity_type FakeModel::type_of(vc_entity entity) const {
  if (entity < 1 || entity > static_cast<vc_entity>(entries_.size()))
    throw FakeError{VC_ERR_BAD_HANDLE, "no entity with id " + std::to_string(entity) + " (ids are 1.." +
                                           std::to_string(entries_.size()) + ")"};
  return entries_[entity - 1].type;
}

int FakeModel::index_of(vc_entity entity, vc_entity_type expected) const {
  vc_entity_type actual = type_of(entity);
  if (actual != expected)
    throw FakeError{VC_ERR_WRONG_TYPE, "entity " + std::to_string(entity) + " is a " + type_name(actual) + ", not a " +
                                           type_name(expected)};
  return entries_[entity - 1].index;
}

const std::string& FakeModel::name(vc_entity entity) const {
  type_of(entity);
  return entries_[entity - 1].name;
}

}  // namespace semimesh::vendor_fake
