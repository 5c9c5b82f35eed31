// The 'vendor' CAD backend: cadapi over the C API of a proprietary kernel (vendor_cad_api.h, in
// the style of CADfix's CFI). The adapter only calls that API; the program links either the
// vendor's SDK (libvendor_cad) or a stand-in that provides the same symbols.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/cad/registry.hpp"
#include "semimesh/cad/source.hpp"

#include <memory>

namespace semimesh::vendor {

/// Loads `source.path` with the vendor kernel. Every entry of `source.params` is handed to the
/// kernel verbatim as a load option ("key=value;..."), so the accepted keys are the kernel's.
/// Entity ids follow the kernel's enumeration order (vertices, edges, faces, each by index).
/// Queries are serialised internally (the kernel allows one thread per session), so the model is
/// thread-safe. Coordinates are not rescaled: units() reports the kernel's unit.
/// Throws cad::CadError naming the vendor function, the entity and the vendor's message.
std::unique_ptr<cad::Model> load_vendor(const cad::Source& source);

/// Registry entry: name "vendor", extension ".vcad", factory load_vendor.
cad::BackendInfo backend_info();

}  // namespace semimesh::vendor
