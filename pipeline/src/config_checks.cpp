#include "config_checks.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <set>

namespace semimesh::pipeline::detail {
namespace {

// ratio_line and ratio_end of `section` (boundary_layer or wall_layer): both or neither, A != B.
void check_ratio_line(Section& s, const std::string& section, const std::optional<std::array<double, 6>>& line,
                      const std::optional<double>& end) {
  if (line) {
    const auto& l = *line;
    const double length2 = (l[3] - l[0]) * (l[3] - l[0]) + (l[4] - l[1]) * (l[4] - l[1]) + (l[5] - l[2]) * (l[5] - l[2]);
    s.require(length2 > 0.0, "ratio_line", "[xa, ya, za, xb, yb, zb] with A != B");
    s.require(end.has_value(), "ratio_line", "together with " + section + ".ratio_end (the ratio at B)");
  }
  if (end) s.require(line.has_value(), "ratio_end", "together with " + section + ".ratio_line (where it applies)");
}

// geometry.wall_plane and geometry.farfield = {box | sphere | box_chords}: complete, together, and
// for a generated wing (which stands on z = 0 and has a box) the plane z = 0 and a box.
void check_generated_domain(const GeometryConfig& geo, Section& plane, Section& join, Section& far, Section& sphere) {
  const WallPlaneConfig& w = geo.wall_plane;
  const FarFieldShapeConfig& f = geo.farfield_shape;
  if (geo.join.given()) {
    join.require(geo.join.body.has_value(), "body", "together with geometry.join.wall: the body's faces in the file");
    join.require(geo.join.wall.has_value(), "wall", "together with geometry.join.body: the wall part's faces in the file");
    join.require(!w.given(), "wall", "unset with [geometry.wall_plane]: an assembly's body stands on its wall part");
    join.require(!geo.source.empty() && geo.backend == "occ", "body",
                 "a CAD file's faces (source = \"...\", backend = \"occ\"): the parts are joined by OpenCASCADE");
    join.require(f.box || f.sphere.centre, "body",
                 "together with geometry.farfield = {box = [...]} or {sphere = {centre, radius}} (box_chords measures "
                 "a root the parts do not have before they are joined)");
  }
  if (w.given()) {
    plane.require(w.point.has_value(), "normal", "together with geometry.wall_plane.point");
    plane.require(w.normal.has_value(), "point", "together with geometry.wall_plane.normal (into the fluid)");
    const auto& n = *w.normal;
    plane.require(n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0, "normal", "a non-zero vector (into the fluid)");
  }
  if (f.sphere.centre || f.sphere.radius) {
    sphere.require(f.sphere.centre.has_value(), "radius", "together with geometry.farfield.sphere.centre");
    sphere.require(f.sphere.radius.has_value(), "centre", "together with geometry.farfield.sphere.radius");
  }
  const int shapes = (f.box ? 1 : 0) + (f.sphere.centre ? 1 : 0) + (f.box_chords ? 1 : 0);
  if (f.box) {
    const auto& b = *f.box;
    far.require(b[0] < b[3] && b[1] < b[4] && b[2] < b[5], "box", "[xmin, ymin, zmin, xmax, ymax, zmax] with each min < max");
    far.require(shapes == 1, "box", "one of box, sphere or box_chords");
  }
  if (f.box_chords) far.require(shapes == 1, "box_chords", "one of box, sphere or box_chords");
  if (geo.join.given() || (!w.given() && !f.given())) return;
  if (f.given())
    plane.require(w.given(), "point",
                  "geometry.wall_plane = {point, normal} together with geometry.farfield = {...}: a body-only file "
                  "gets both its wall and its far field");
  else
    plane.require(false, "point",
                  "together with geometry.farfield = {box = [...]} | {sphere = {centre, radius}} | {box_chords = k}: "
                  "a body-only file gets both its wall and its far field");
  if (!geo.source.empty()) return;
  // The generated wing stands on z = 0 in a box of its own.
  const auto& p = *w.point;
  const auto& n = *w.normal;
  plane.require(p[2] == 0.0 && n[0] == 0.0 && n[1] == 0.0 && n[2] > 0.0, "normal",
                "the plane z = 0 with normal +z for a generated wing (it stands on z = 0; give a CAD file with "
                "backend = \"occ\" for another plane)");
  if (f.sphere.centre)
    sphere.require(false, "centre",
                   "a box for a generated wing (its far field is a box; a sphere needs a CAD file with backend = "
                   "\"occ\")");
}

// [geometry] and its subsections: the CAD file's path, its units, the generated wing's box and tip,
// the wall plane and far field of a body-only file.
void check_geometry(Config& c, const std::map<std::string, Section*>& sections, const std::string& base_directory) {
  GeometryConfig& geo = c.geometry;
  if (!geo.source.empty() && !base_directory.empty() && std::filesystem::path(geo.source).is_relative())
    geo.source = (std::filesystem::path(base_directory) / geo.source).lexically_normal().string();
  Section& g = *sections.at("geometry");
  g.require(geo.source.empty() || geo.units != "chord", "units",
            "a length unit for a CAD file (mm, cm, m, km, um, in, ft), or \"auto\" for the one it declares");
  g.require(!geo.source.empty() || !geo.sew_tolerance, "sew_tolerance", "unset for a generated wing (no file to sew)");
  const auto& box = geo.naca.box;
  sections.at("geometry.naca")
      ->require(box[0] < box[3] && box[1] < box[4] && box[2] < box[5], "box",
                "[xmin, ymin, zmin, xmax, ymax, zmax] with each min < max");

  sections.at("geometry.naca")
      ->require(geo.naca.tip == "flat" || !geo.source.empty() || geo.backend == "naca", "tip",
                "\"flat\" for backend \"" + geo.backend + "\" (the rounded tip is the analytic backend's: backend = \"naca\")");
  // A sharp trailing edge closes the rounded tip to a cone's apex (half angle ~8 degrees for 0012):
  // at order 1 its prisms are valid, curved they fold there (4 invalid at order 4 on the coarse
  // case, at every shell thickness and surface size tried: the apex is self-similar).
  sections.at("geometry.naca")
      ->require(geo.naca.tip == "flat" || geo.naca.te == "blunt" || c.highorder.order == 1, "tip",
                "\"flat\" with te = \"sharp\" at highorder.order > 1 (a sharp trailing edge closes the rounded tip "
                "to a conical point where curved prisms fold), or te = \"blunt\", or highorder.order = 1");

  // The fuselage and the dihedral are the analytic backend's; the fuselage is the wall, so no wall
  // plane goes with it.
  Section& naca = *sections.at("geometry.naca");
  naca.require(geo.naca.wall == "plane" || (geo.source.empty() && geo.backend == "naca"), "wall",
               "\"plane\" for backend \"" + geo.backend + "\"" + (geo.source.empty() ? "" : " with a source file") +
                   " (the fuselage walls are the analytic backend's: backend = \"naca\", no source)");
  naca.require(geo.naca.wall == "plane" || !geo.wall_plane.given(), "wall",
               "\"plane\" with [geometry.wall_plane] (the fuselage is the wall)");
  naca.require(!geo.naca.wall_radius || geo.naca.wall != "plane", "wall_radius",
               "unset unless wall = \"cylinder\" or \"cone\"");
  naca.require(!geo.naca.wall_angle || geo.naca.wall == "cone", "wall_angle", "unset unless wall = \"cone\"");
  naca.require(geo.naca.dihedral == 0.0 || (geo.source.empty() && geo.backend == "naca"), "dihedral",
               "0 for backend \"" + geo.backend + "\"" + (geo.source.empty() ? "" : " with a source file") +
                   " (the dihedral is the analytic backend's: backend = \"naca\", no source)");

  check_generated_domain(geo, *sections.at("geometry.wall_plane"), *sections.at("geometry.join"),
                         *sections.at("geometry.farfield"), *sections.at("geometry.farfield.sphere"));

  // The cut is made on the CAD file's body before the far field is built around it.
  Section& cut = *sections.at("geometry.body_cut");
  if (geo.body_cut.given()) {
    cut.require(geo.body_cut.point.has_value(), "normal", "together with geometry.body_cut.point");
    cut.require(geo.body_cut.normal.has_value(), "point", "together with geometry.body_cut.normal");
    const auto n = geo.body_cut.normal.value_or(std::array<double, 3>{1, 0, 0});
    cut.require(n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0, "normal", "a non-zero vector (towards the part taken away)");
    cut.require(!geo.source.empty() && geo.backend == "occ" && (geo.wall_plane.given() || geo.join.given()), "point",
                "a CAD file's body the far field is built around (backend = \"occ\", source = \"...\", with "
                "[geometry.wall_plane] or [geometry.join])");
  }
}

// [nearfield]: the H-type needs a wall layer; the junction's angles in order.
void check_nearfield(const Config& c, Section& n) {
  n.require(c.nearfield.topology != "H" || c.wall_layer.thickness > 0.0, "topology",
            "\"O\" or \"C\" with wall_layer.thickness = 0: the H-type wake block stands a gap above the wall layer");
  const nearfield::JunctionParams& junction = c.nearfield.junction;
  n.require(junction.min_angle_deg < junction.max_angle_deg, "junction_min_angle", "< nearfield.junction_max_angle");
  n.require(junction.max_angle_deg <= junction.concave_below_deg, "junction_max_angle", "<= nearfield.concave_angle");
}

// [wall_layer] and [boundary_layer]: one way to give the first cell, fitting in its layer; ratio_line
// with ratio_end; y_plus with reynolds.
void check_layers(const Config& c, Section& b, Section& w) {
  const WallLayerConfig& wall = c.wall_layer;
  if (wall.first_cell_height) {
    w.require(!w.has("ratio"), "first_cell_height", "either ratio or first_cell_height, not both");
    w.require(*wall.first_cell_height * wall.split.layers <= wall.thickness, "first_cell_height",
              fmt::format("<= wall_layer.thickness / layers = {}", wall.thickness / wall.split.layers) +
                  " (the layers must fit in the wall layer with a ratio >= 1)");
  }

  const BoundaryLayerConfig& layer = c.boundary_layer;
  const double thickness = c.nearfield.shell.thickness;
  if (layer.first_cell_height) {
    b.require(!b.has("ratio"), "first_cell_height", "either ratio or first_cell_height, not both");
    b.require(*layer.first_cell_height * layer.split.layers <= thickness, "first_cell_height",
              fmt::format("<= nearfield.thickness / layers = {}", thickness / layer.split.layers) +
                  " (the layers must fit in the shell with a ratio >= 1)");
  }
  check_ratio_line(b, "boundary_layer", layer.ratio_line, layer.ratio_end);
  check_ratio_line(w, "wall_layer", wall.ratio_line, wall.ratio_end);
  if (layer.y_plus) {
    b.require(layer.reynolds.has_value(), "y_plus", "together with boundary_layer.reynolds");
    b.require(!b.has("ratio") && !layer.first_cell_height, "y_plus",
              "either y_plus, ratio or first_cell_height, one of them");
  }
  if (layer.reynolds) b.require(layer.y_plus.has_value(), "reynolds", "together with boundary_layer.y_plus");
}

// [output]: each format once, a bare file name.
void check_output(const Config& c, Section& o, Section& highorder) {
  const std::set<std::string> distinct(c.output.formats.begin(), c.output.formats.end());
  o.require(distinct.size() == c.output.formats.size(), "formats", "each format at most once");
  o.require(c.output.basename.find('/') == std::string::npos, "basename", "a file name without folder, e.g. \"wing\"");
  if (c.output.target == OutputTarget::Pyfr) {
    // PyFR's gmsh reader takes ASCII MSH only, and element types up to order 4.
    o.require(distinct.count("msh41-ascii") + distinct.count("msh22") > 0, "formats",
              "with target = \"pyfr\": \"msh41-ascii\" or \"msh22\" among them (PyFR reads ASCII MSH only; "
              "\"msh41\" is binary)");
    highorder.require(c.highorder.order <= 4, "order", "at most 4 with output.target = \"pyfr\" (PyFR's importer)");
  }
}

}  // namespace

void check_across_keys(Config& c, const std::map<std::string, Section*>& sections, const std::string& base_directory) {
  check_geometry(c, sections, base_directory);
  check_nearfield(c, *sections.at("nearfield"));
  check_layers(c, *sections.at("boundary_layer"), *sections.at("wall_layer"));
  sections.at("sizing")->require(c.sizing.size.min_size <= c.sizing.size.max_size, "min_size",
                                 "in (0, sizing.max_size]");
  check_output(c, *sections.at("output"), *sections.at("highorder"));
}

}  // namespace semimesh::pipeline::detail
