// How near-field messages name places: CAD surfaces as everywhere (cad/labels.hpp), points by
// coordinates.
#pragma once

#include "semimesh/cad/labels.hpp"

#include <sstream>
#include <string>

namespace semimesh::nearfield {

using cad::surface_label;

inline std::string number_label(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

/// "surface 6 ('a'), surface 9 ('b')": several surfaces, as one message names them.
template <class Ids>
std::string surfaces_label(const cad::Model& model, const Ids& surfaces) {
  std::string text;
  for (int s : surfaces) text += (text.empty() ? "" : ", ") + surface_label(model, s);
  return text;
}

inline std::string point_label(const cad::Vec3& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

}  // namespace semimesh::nearfield
