#include "semimesh/backends/builtin.hpp"

#include "semimesh/mock_cad/naca.hpp"
#ifdef SEMIMESH_HAVE_OCC
#include "semimesh/occ/occ_backend.hpp"
#endif
#ifdef SEMIMESH_HAVE_VENDOR_SDK
#include "semimesh/vendor/vendor_backend.hpp"
#endif

namespace semimesh::backends {

cad::Registry default_registry() {
  cad::Registry registry;
  registry.add(cad::BackendInfo{"naca", "analytic NACA 4-digit wing on a wall, in a far-field box (exact geometry)",
                                {}, &mock_cad::load_naca, {}});

  const std::string occ_description = "OpenCASCADE: STEP, IGES, BREP and FreeCAD files; B-spline NACA wing without a file";
#ifdef SEMIMESH_HAVE_OCC
  registry.add(cad::BackendInfo{"occ", occ_description, {".step", ".stp", ".iges", ".igs", ".brep", ".brp", ".fcstd"},
                                &occ::load_occ, {}});
#else
  registry.add_unavailable("occ", occ_description, "built without OpenCASCADE");
#endif

#ifdef SEMIMESH_HAVE_VENDOR_SDK
  registry.add(vendor::backend_info());
#else
  registry.add_unavailable("vendor", "proprietary CAD kernel through its C API (CFI-style adapter)", "vendor SDK not found");
#endif
  return registry;
}

}  // namespace semimesh::backends
