// The fake kernel's view of a model: the analytic geometry plus the kernel's own conventions,
// which differ from semimesh's on purpose so the adapter's translation is exercised:
//  - entity ids are 1-based and shared by all types, numbered body, faces, edges, vertices
//    (so a vertex's id is not its index);
//  - a face stores a "reversed" flag relative to its natural normal du x dv, and its loops run
//    counter-clockwise around that natural normal (semimesh's run around the fluid normal).
#pragma once

#include "fake_error.hpp"

#include "semimesh/cad/model.hpp"

#include <memory>
#include <string>
#include <vector>

namespace semimesh::vendor_fake {

/// An edge as walked by a loop, in kernel terms.
struct EdgeUse {
  vc_entity edge = VC_NULL_ENTITY;
  vc_sense sense = VC_SENSE_SAME;
};

class FakeModel {
 public:
  FakeModel(std::unique_ptr<cad::Model> geometry, vc_unit units, double tolerance);

  const cad::Model& geometry() const { return *geometry_; }
  vc_unit units() const { return units_; }
  double tolerance() const { return tolerance_; }

  int count(vc_entity_type type) const;
  /// The index-th (1-based) entity of a type; FakeError(OUT_OF_RANGE) past the count.
  vc_entity entity(vc_entity_type type, int index) const;
  /// Type of an entity; FakeError(BAD_HANDLE) when the model has no such id.
  vc_entity_type type_of(vc_entity entity) const;
  /// 0-based index of the entity among its type in the geometry; FakeError(BAD_HANDLE /
  /// WRONG_TYPE) when it is not an entity of `expected` type.
  int index_of(vc_entity entity, vc_entity_type expected) const;
  const std::string& name(vc_entity entity) const;

  /// Face (0-based index) uses the reversed natural normal in the body.
  bool reversed(int face) const { return reversed_[face]; }
  /// Loops of a face (0-based index) in kernel convention, outer first.
  const std::vector<std::vector<EdgeUse>>& loops(int face) const { return loops_[face]; }

 private:
  struct Entry {
    vc_entity_type type;
    int index;  // 0-based among its type
    std::string name;
  };
  vc_entity first_id(vc_entity_type type) const;

  std::unique_ptr<cad::Model> geometry_;
  vc_unit units_;
  double tolerance_;
  std::vector<Entry> entries_;  // by id - 1
  std::vector<bool> reversed_;
  std::vector<std::vector<std::vector<EdgeUse>>> loops_;
};

}  // namespace semimesh::vendor_fake
