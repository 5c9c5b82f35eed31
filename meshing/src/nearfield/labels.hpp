// How near-field messages name places: CAD surfaces by name and id, points by coordinates.
#pragma once

#include "semimesh/cad/model.hpp"

#include <sstream>
#include <string>

namespace semimesh::nearfield {

inline std::string surface_label(const cad::Model& model, int s) {
  return "surface '" + model.surface(s).name() + "' (id " + std::to_string(s) + ")";
}

inline std::string number_label(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

inline std::string point_label(const cad::Vec3& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

}  // namespace semimesh::nearfield
