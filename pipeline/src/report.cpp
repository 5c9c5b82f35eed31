#include "semimesh/pipeline/report.hpp"

#include "semimesh/io/json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <string>

namespace semimesh::pipeline {
namespace {

using io::json_number;
using io::json_string;

template <typename Items, typename Format>
std::string json_list(const Items& items, Format format) {
  std::string out = "[";
  bool first = true;
  for (const auto& item : items) {
    out += (first ? "" : ", ") + format(item);
    first = false;
  }
  return out + "]";
}

std::string json_counts(const std::map<std::string, std::size_t>& counts) {
  std::string out = "{";
  for (const auto& [key, count] : counts) out += (out.size() > 1 ? ", " : "") + json_string(key) + ": " + std::to_string(count);
  return out + "}";
}

}  // namespace

std::string summary_table(const RunResult& r) {
  std::string t;
  for (const std::string& repair : r.model_repairs) t += fmt::format("CAD as loaded: {}\n", repair);
  t += fmt::format("{:<28} {:>12}\n", "elements (order " + std::to_string(r.mesh.order()) + ")", r.mesh.elements().size());
  for (const auto& [type, count] : r.elements_by_type) t += fmt::format("  {:<26} {:>12}\n", type, count);
  if (r.elements_by_region.size() > 1)
    for (const auto& [region, count] : r.elements_by_region) {
      const auto jacobian = r.validity.min_scaled_jacobian_by_region.find(region);
      t += fmt::format("  region {:<19} {:>12}", region, count);
      t += jacobian == r.validity.min_scaled_jacobian_by_region.end()
               ? "\n" : fmt::format("   min scaled Jacobian {:.4f}\n", jacobian->second);
    }
  if (r.junction_hexes > 0) t += fmt::format("{:<28} {:>12}\n", "junction hexes (unsplit)", r.junction_hexes);
  if (r.wake.hexes > 0) {
    t += fmt::format("{:<28} {:>12}\n", "wake hexes (unsplit)", r.wake.hexes);
    t += fmt::format("{:<28} {:>12.4g}\n", "wake length", r.wake.length);
    t += fmt::format("{:<28} {:>12}\n", "wake streamwise cells", r.wake.streamwise_cells);
    t += fmt::format("{:<28} {:>12.4g}\n", "wake ratio at the TE", r.wake.ratio_first);
    t += fmt::format("{:<28} {:>12.4g}\n", "wake ratio at the far end", r.wake.ratio_last);
    t += fmt::format("{:<28} {:>12.4g}\n", "wake gap above wall layer", r.wake.gap);
  }
  t += fmt::format("{:<28} {:>12}\n", "nodes", r.mesh.num_nodes());
  for (const auto& [group, count] : r.boundary_faces_by_group) t += fmt::format("  boundary {:<17} {:>12}\n", group, count);
  t += fmt::format("{:<28} {:>12}\n", "invalid elements", r.validity.invalid);
  t += fmt::format("{:<28} {:>12.4f}\n", "min scaled Jacobian", r.validity.min_scaled_jacobian);
  t += fmt::format("{:<28} {:>12.4f}\n", "median scaled Jacobian", r.validity.median_scaled_jacobian);
  t += fmt::format("{:<28} {:>12}\n", "conformity problems", r.conformity.problems.size());
  t += fmt::format("{:<28} {:>12.3e}\n", "volume error vs boundary", r.volume.mesh.boundary_relative_error());
  t += fmt::format("{:<28} {:>12.3e}\n", "volume error vs box - body", r.volume.expected_relative_error());
  t += fmt::format("{:<28} {:>12.4g}\n", "layer thickness min", r.thickness_min);
  t += fmt::format("{:<28} {:>12.4g}\n", "layer thickness max", r.thickness_max);
  t += fmt::format("{:<28} {:>12}\n", "boundary layers", r.layers.layers);
  if (r.layers.layers > 1) {
    t += fmt::format("{:<28} {:>12.4g}\n", "first cell height min", r.layers.first_cell_height_min);
    t += fmt::format("{:<28} {:>12.4g}\n", "first cell height max", r.layers.first_cell_height_max);
    if (r.layers.first_cell_height_target > 0.0)
      t += fmt::format("{:<28} {:>12.4g}\n{:<28} {:>5.3g} .. {:<5.3g}\n", "first cell height for y+",
                       r.layers.first_cell_height_target, "y+ of the first cells", r.layers.y_plus_min, r.layers.y_plus_max);
    t += fmt::format("{:<28} {:>12.4f}\n", "layer ratio (achieved)", r.layers.achieved_ratio);
    t += fmt::format("{:<28} {:>12.4g}\n", "max first-layer aspect", r.layers.max_first_layer_aspect);
  }
  if (r.wall_layers.layers > 1) {
    t += fmt::format("{:<28} {:>12}\n", "wall layers", r.wall_layers.layers);
    t += fmt::format("{:<28} {:>12.4g}\n", "wall first cell height min", r.wall_layers.first_cell_height_min);
    t += fmt::format("{:<28} {:>12.4g}\n", "wall first cell height max", r.wall_layers.first_cell_height_max);
    t += fmt::format("{:<28} {:>12.4f}\n", "wall layer ratio (achieved)", r.wall_layers.achieved_ratio);
  }
  if (r.mesh.order() > 1) {
    t += fmt::format("{:<28} {:>12}\n", "node placement", r.node_placement);
    t += fmt::format("{:<28} {:>12.4g}\n", "max node move onto CAD", r.curving.max_projection_distance);
    if (r.curving.optimisation_fallbacks > 0)
      t += fmt::format("{:<28} {:>12}\n", "spring fallbacks", r.curving.optimisation_fallbacks);
    if (r.curving.kinked_surfaces + r.curving.kinked_curves > 0)
      t += fmt::format("{:<28} {:>12}\n", "kinked parameters (s / c)",
                       fmt::format("{} / {}", r.curving.kinked_surfaces, r.curving.kinked_curves));
  }
  t += fmt::format("{:<28} {:>12.3e}\n", "geometric error max / chord", r.geometric_error.max_rel);
  t += fmt::format("{:<28} {:>12.3e}\n", "geometric error rms / chord", r.geometric_error.rms_rel);
  for (const StageTiming& s : r.stages) t += fmt::format("  time {:<21} {:>10.3f} s\n", s.name, s.seconds);
  t += fmt::format("{:<28} {:>10.3f} s\n", "time total", r.total_seconds());
  t += fmt::format("{:<28} {:>9.1f} MB\n", "peak memory", r.peak_memory_mb);
  for (const std::string& f : r.written_files) t += "wrote " + f + "\n";
  return t;
}

std::string report_json(const RunResult& r, const Config& config) {
  std::string j = "{\n";
  j += fmt::format("  \"order\": {},\n", r.mesh.order());
  j += fmt::format("  \"requested_order\": {},\n", config.highorder.order);
  j += fmt::format("  \"nodes\": {},\n", r.mesh.num_nodes());
  j += fmt::format("  \"elements\": {},\n", r.mesh.elements().size());
  j += "  \"elements_by_type\": " + json_counts(r.elements_by_type) + ",\n";
  j += "  \"elements_by_region\": " + json_counts(r.elements_by_region) + ",\n";
  j += fmt::format("  \"junction_hexes\": {},\n", r.junction_hexes);
  j += fmt::format("  \"wake\": {{\"hexes\": {}, \"length\": {}, \"streamwise_cells\": {}, \"ratio_first\": {}, "
                   "\"ratio_last\": {}, \"gap\": {}}},\n",
                   r.wake.hexes, json_number(r.wake.length), r.wake.streamwise_cells, json_number(r.wake.ratio_first),
                   json_number(r.wake.ratio_last), json_number(r.wake.gap));
  j += "  \"boundary_faces_by_group\": " + json_counts(r.boundary_faces_by_group) + ",\n";
  j += fmt::format("  \"surface_triangles\": {},\n  \"surface_quads\": {},\n", r.surface_triangles, r.surface_quads);
  j += fmt::format("  \"far_field\": {{\"tets\": {}, \"pyramids\": {}, \"wall_triangles\": {}, \"box_triangles\": {}, "
                   "\"interior_points\": {}, \"tetgen_added_points\": {}, \"tetgen_seconds\": {}, \"tetgen_untied\": {}}},\n",
                   r.far_field.tets, r.far_field.pyramids, r.far_field.wall_triangles, r.far_field.box_triangles,
                   r.far_field.interior_points, r.far_field.added_points, json_number(r.far_field.seconds_tetgen),
                   r.far_field.tetgen_untied);
  if (config.output.target == OutputTarget::Pyfr)
    j += fmt::format("  \"pyfr_split\": {{\"pyramids_refused\": {}, \"columns\": {}, \"hexes_to_prisms\": {}, "
                     "\"pyramids_to_tets\": {}, \"boundary_quads_to_triangles\": {}}},\n",
                     r.pyfr_columns.pyramids_refused, r.pyfr_columns.columns, r.pyfr_columns.hexes_split,
                     r.pyfr_columns.pyramids_split, r.pyfr_columns.boundary_quads_split);
  j += fmt::format("  \"thickness_min\": {},\n  \"thickness_max\": {},\n", json_number(r.thickness_min),
                   json_number(r.thickness_max));
  j += fmt::format("  \"layers\": {},\n  \"layer_ratio\": {},\n  \"achieved_layer_ratio\": {},\n", r.layers.layers,
                   json_number(r.layers.requested_ratio), json_number(r.layers.achieved_ratio));
  j += fmt::format("  \"layer_ratio_end\": {},\n", json_number(r.layers.requested_ratio_end));
  j += fmt::format("  \"first_cell_height_min\": {},\n  \"first_cell_height_max\": {},\n",
                   json_number(r.layers.first_cell_height_min), json_number(r.layers.first_cell_height_max));
  if (r.layers.first_cell_height_target > 0.0)
    j += fmt::format("  \"first_cell_height_target\": {},\n  \"y_plus_min\": {},\n  \"y_plus_max\": {},\n",
                     json_number(r.layers.first_cell_height_target), json_number(r.layers.y_plus_min),
                     json_number(r.layers.y_plus_max));
  j += fmt::format("  \"max_first_layer_aspect_ratio\": {},\n", json_number(r.layers.max_first_layer_aspect));
  j += fmt::format("  \"wall_layer\": {{\"layers\": {}, \"ratio\": {}, \"achieved_ratio\": {}, "
                   "\"first_cell_height_min\": {}, \"first_cell_height_max\": {}}},\n",
                   r.wall_layers.layers, json_number(r.wall_layers.requested_ratio),
                   json_number(r.wall_layers.achieved_ratio), json_number(r.wall_layers.first_cell_height_min),
                   json_number(r.wall_layers.first_cell_height_max));
  j += fmt::format("  \"geometric_error\": {{\"max_rel\": {}, \"rms_rel\": {}, \"reference_length\": {}, "
                   "\"samples\": {}}},\n",
                   json_number(r.geometric_error.max_rel), json_number(r.geometric_error.rms_rel),
                   json_number(r.geometric_error.reference_length), r.geometric_error.samples);
  j += fmt::format("  \"curving\": {{\"node_placement\": {}, \"edges_on_curves\": {}, \"edges_on_surfaces\": {}, "
                   "\"faces_on_surfaces\": {}, \"spring_fallbacks\": {}, \"kinked_surfaces\": {}, \"kinked_curves\": {}, "
                   "\"max_node_move\": {}}},\n",
                   json_string(r.node_placement), r.curving.edges_on_curves, r.curving.edges_on_surfaces,
                   r.curving.faces_on_surfaces, r.curving.optimisation_fallbacks, r.curving.kinked_surfaces,
                   r.curving.kinked_curves,
                   json_number(r.curving.max_projection_distance));
  j += fmt::format("  \"invalid_elements\": {},\n", r.validity.invalid);
  j += fmt::format("  \"min_scaled_jacobian\": {},\n", json_number(r.validity.min_scaled_jacobian));
  j += fmt::format("  \"min_scaled_jacobian_floor\": {},\n", json_number(r.validity.floor));
  j += fmt::format("  \"median_scaled_jacobian\": {},\n", json_number(r.validity.median_scaled_jacobian));
  j += fmt::format("  \"inherited_bounds\": {},\n", r.validity.inherited);
  {
    std::string by_region = "{";
    for (const auto& [region, value] : r.validity.min_scaled_jacobian_by_region)
      by_region += (by_region.size() > 1 ? ", " : "") + json_string(region) + ": " + json_number(value);
    j += "  \"min_scaled_jacobian_by_region\": " + by_region + "},\n";
  }
  j += fmt::format("  \"conformity_problems\": {},\n", r.conformity.problems.size());
  j += fmt::format("  \"interior_faces\": {},\n  \"boundary_faces\": {},\n", r.conformity.interior_faces,
                   r.conformity.boundary_faces);
  j += fmt::format("  \"volume\": {{\"elements\": {}, \"boundary\": {}, \"box\": {}, \"body\": {}, "
                   "\"error_vs_boundary\": {}, \"error_vs_box_minus_body\": {}}},\n",
                   json_number(r.volume.mesh.element_volume), json_number(r.volume.mesh.boundary_volume),
                   json_number(r.volume.box_volume), json_number(r.volume.body_volume),
                   json_number(r.volume.mesh.boundary_relative_error()), json_number(r.volume.expected_relative_error()));
  j += fmt::format("  \"checks_passed\": {},\n", r.checks_passed() ? "true" : "false");
  j += "  \"stages\": " + json_list(r.stages, [](const StageTiming& s) {
         return fmt::format("{{\"name\": {}, \"seconds\": {}}}", json_string(s.name), json_number(s.seconds));
       }) + ",\n";
  j += fmt::format("  \"total_seconds\": {},\n", json_number(r.total_seconds()));
  j += fmt::format("  \"peak_memory_mb\": {},\n", json_number(r.peak_memory_mb));
  j += "  \"model_repairs\": " + json_list(r.model_repairs, json_string) + ",\n";
  j += "  \"warnings\": " + json_list(r.warnings, json_string) + ",\n";
  j += "  \"pictures\": " + json_list(r.pictures, json_string) + ",\n";
  j += "  \"files\": " + json_list(r.written_files, json_string) + "\n}\n";
  return j;
}

}  // namespace semimesh::pipeline
