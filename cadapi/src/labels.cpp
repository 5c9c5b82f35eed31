#include "semimesh/cad/labels.hpp"

namespace semimesh::cad {

std::string surface_label(const Model& model, int surface) {
  return "surface " + std::to_string(surface) + " ('" + model.surface(surface).name() + "')";
}

std::string curve_label(const Model& model, int curve) {
  return "curve " + std::to_string(curve) + " ('" + model.curve(curve).name() + "')";
}

}  // namespace semimesh::cad
