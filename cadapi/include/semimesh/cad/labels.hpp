// How every message names a CAD entity: its kind, id and name, e.g. "surface 7 ('upper')", so a
// user can find it in `semimesh cad-info` and in the CAD tool.
#pragma once

#include "semimesh/cad/model.hpp"

#include <string>

namespace semimesh::cad {

std::string surface_label(const Model& model, int surface);
std::string curve_label(const Model& model, int curve);

}  // namespace semimesh::cad
