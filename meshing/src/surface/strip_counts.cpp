// Equal segment counts on the opposite curves of structured strips, set before any surface is
// meshed so that the strip and its neighbours share the same curve meshes.
#include "semimesh/cad/labels.hpp"
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/model_surfaces.hpp"

namespace semimesh::surface {

void equalise_strip_counts(const cad::Model& model, const SizeField& size, const std::set<int>& strips,
                           const std::map<int, CurveCount>& prescribed, std::vector<CurveMesh>& curves) {
  std::set<int> fixed;  // curves whose count is imposed: prescribed, or set from a prescribed one
  for (const auto& entry : prescribed) fixed.insert(entry.first);
  // Each pass raises a free count or fixes a curve, so the counts settle after at most
  // (curves + 1) passes of changes; one more pass confirms.
  for (int pass = 0; pass <= model.num_curves() + 1; ++pass) {
    bool changed = false;
    for (int s : strips) {
      const auto& loops = model.loops(s);
      if (loops.size() != 1 || loops[0].uses.size() != 4) continue;
      for (int k = 0; k < 2; ++k) {
        const int a = loops[0].uses[k].curve, b = loops[0].uses[k + 2].curve;
        if (model.curve(a).is_degenerate() || model.curve(b).is_degenerate()) continue;
        const int na = curves[a].segments(), nb = curves[b].segments();
        if (na == nb) continue;
        const bool fa = fixed.count(a) > 0, fb = fixed.count(b) > 0;
        if (fa && fb)
          throw SurfaceMeshError(cad::surface_label(model, s) + ": opposite curves " + cad::curve_label(model, a) +
                                 " (" + std::to_string(na) + " segments) and " + cad::curve_label(model, b) + " (" +
                                 std::to_string(nb) + ") of a structured strip both have prescribed counts");
        // The imposed count wins; between two free curves, the larger one.
        const bool raise_b = fa || (!fb && na > nb);
        const int target = raise_b ? b : a;
        curves[target] = discretise_curve_to_count(model, target, size, raise_b ? na : nb);
        if (fa || fb) fixed.insert(target);
        changed = true;
      }
    }
    if (!changed) return;
  }
  throw SurfaceMeshError("structured strips: the opposite-curve segment counts did not settle");
}

}  // namespace semimesh::surface
