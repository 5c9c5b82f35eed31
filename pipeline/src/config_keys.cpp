// The configuration's sections and their keys (config_sections): one params table per section,
// built from the stages' own tables (nearfield, surface, farfield, ho) and the pipeline's rows.
#include "semimesh/pipeline/config.hpp"

#include "semimesh/pipeline/output_formats.hpp"

#include <string>
#include <vector>

namespace semimesh::pipeline {
namespace {

template <class Outer, class Inner>
void append(params::Table<Outer>& table, Inner Outer::*member, const params::Table<Inner>& inner) {
  for (auto& k : params::nested(member, inner)) table.push_back(std::move(k));
}

// A table of [geometry]'s sub-table `member`, as the config's keys.
template <class Inner>
params::Table<Config> geometry_table(Inner GeometryConfig::*member, const params::Table<Inner>& keys) {
  params::Table<GeometryConfig> g;
  append(g, member, keys);
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> geometry_keys() {
  params::Table<GeometryConfig> g = {
      params::string("backend", &GeometryConfig::backend, "non-empty",
                     "CAD kernel from the registry: naca (analytic wing), occ (OpenCASCADE), vendor"),
      params::string("source", &GeometryConfig::source, "",
                     "CAD file, relative to the config file's folder; empty: the generated wing"),
      params::string("units", &GeometryConfig::units,
                     "\"auto\" | \"mm\" | \"cm\" | \"m\" | \"km\" | \"um\" | \"in\" | \"ft\" | \"chord\"",
                     "the unit of the model's numbers (a CAD file's after scale), overriding the one the file declares; "
                     "\"auto\": the declared one (chord for a generated wing). Sizes in this config are in it"),
      params::real("scale", &GeometryConfig::scale, "> 0", "factor applied to a CAD file's coordinates at load"),
      params::real("sew_tolerance", &GeometryConfig::sew_tolerance, "> 0",
                   "CAD file: faces whose edges lie closer than this (model units) are sewn together; unset: from "
                   "1e-6 of the model's diagonal, raised tenfold up to 1e-4 while that closes more gaps"),
      params::strings("body", &GeometryConfig::body, "non-empty",
                      "surfaces wrapped by the near-field shell: names, ids (\"#7\") or \"auto\" (found from the model)"),
      params::string("wall", &GeometryConfig::wall, "non-empty",
                     "the planar wall the body stands on: a name, an id or \"auto\" (the face holding the root loop)"),
      params::strings("farfield", &GeometryConfig::farfield, "non-empty",
                      "the outer boundary's surfaces: names, ids or \"auto\" (every face neither body nor wall); or "
                      "a table: the far field to build around a body-only file ([geometry.farfield])"),
  };
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> wall_plane_keys() {
  params::Table<WallPlaneConfig> w = {
      params::reals("point", &WallPlaneConfig::point, "", "a point of the wall plane (model units)"),
      params::reals("normal", &WallPlaneConfig::normal, "", "the plane's normal, pointing into the fluid"),
  };
  return geometry_table(&GeometryConfig::wall_plane, w);
}

params::Table<Config> body_cut_keys() {
  params::Table<WallPlaneConfig> c = {
      params::reals("point", &WallPlaneConfig::point, "", "a point of the cutting plane (model units)"),
      params::reals("normal", &WallPlaneConfig::normal, "",
                    "the plane's normal, pointing to the part of the body to take away (non-zero)"),
  };
  return geometry_table(&GeometryConfig::body_cut, c);
}

params::Table<Config> join_keys() {
  params::Table<JoinConfig> j = {
      params::strings("body", &JoinConfig::body, "non-empty",
                      "the body's faces in the file (a wing reaching into the wall part): ids (\"#7\", as "
                      "`semimesh cad-info FILE` numbers them) or names (every face of the name)"),
      params::strings("wall", &JoinConfig::wall, "non-empty", "the wall part's faces in the file (a fuselage, a hub): ids or names"),
  };
  return geometry_table(&GeometryConfig::join, j);
}

params::Table<Config> farfield_shape_keys() {
  params::Table<FarFieldShapeConfig> f = {
      params::reals("box", &FarFieldShapeConfig::box, "", "[xmin, ymin, zmin, xmax, ymax, zmax], each min < max"),
      params::real("box_chords", &FarFieldShapeConfig::box_chords, "> 0",
                   "a box this many root chords around the body's bounding box"),
  };
  return geometry_table(&GeometryConfig::farfield_shape, f);
}

params::Table<Config> farfield_sphere_keys() {
  params::Table<FarFieldSphereConfig> s = {
      params::reals("centre", &FarFieldSphereConfig::centre, "", "the sphere's centre"),
      params::real("radius", &FarFieldSphereConfig::radius, "> 0", "the sphere's radius"),
  };
  params::Table<FarFieldShapeConfig> f;
  append(f, &FarFieldShapeConfig::sphere, s);
  return geometry_table(&GeometryConfig::farfield_shape, f);
}

params::Table<Config> naca_keys() {
  params::Table<NacaConfig> n = {
      params::string("code", &NacaConfig::code, "", "NACA 4-digit section MPTT"),
      params::real("chord", &NacaConfig::chord, "> 0", "root chord"),
      params::real("span", &NacaConfig::span, "> 0", "wing height above the wall z = 0"),
      params::real("taper", &NacaConfig::taper, "> 0", "tip chord / root chord"),
      params::real("sweep", &NacaConfig::sweep, "(-80, 80)", "leading-edge sweep, degrees"),
      params::real("dihedral", &NacaConfig::dihedral, "(-45, 45)",
                   "dihedral, degrees: the sections shifted sideways by z tan(dihedral) (backend naca)"),
      params::string("te", &NacaConfig::te, "\"blunt\" | \"sharp\"",
                     "squared-off trailing edge (with a te_base face) or closed"),
      params::string("tip", &NacaConfig::tip, "\"flat\" | \"round\"",
                     "flat tip cap, or round: the tip section revolved about its camber line (backend naca)"),
      params::string("wall", &NacaConfig::wall, "\"plane\" | \"cylinder\" | \"cone\"",
                     "the wall z = 0, or a fuselage along x of radius wall_radius (cone: widening by wall_angle), crest "
                     "through the root's leading edge (backend naca)"),
      params::real("wall_radius", &NacaConfig::wall_radius, "> 0",
                   "the fuselage's radius at x = 0 (wall = \"cylinder\" or \"cone\"); unset: 1.5 chords"),
      params::real("wall_angle", &NacaConfig::wall_angle, "(-30, 30)",
                   "the cone's half angle, degrees, its radius growing downstream (wall = \"cone\"); unset: 5"),
      params::reals("box", &NacaConfig::box, "",
                    "far-field box [xmin, ymin, zmin, xmax, ymax, zmax], each min < max, zmin = 0 (on a fuselage: "
                    "below it; unchanged, the backend's default around the fuselage)"),
  };
  return geometry_table(&GeometryConfig::naca, n);
}

params::Table<Config> nearfield_keys() {
  params::Table<NearFieldConfig> n = {
      params::string("topology", &NearFieldConfig::topology, "\"O\" | \"C\" | \"H\"",
                     "near-field partition: O one prism layer, C plus the root junction and the wall layer, H plus the wake block"),
  };
  append(n, &NearFieldConfig::shell, nearfield::shell_keys());
  append(n, &NearFieldConfig::junction, nearfield::junction_keys());
  params::Table<Config> table;
  append(table, &Config::nearfield, n);
  return table;
}

params::Table<Config> boundary_layer_keys() {
  params::Table<BoundaryLayerConfig> b;
  append(b, &BoundaryLayerConfig::split, ho::layer_keys());
  b.push_back(params::real("first_cell_height", &BoundaryLayerConfig::first_cell_height, "> 0",
                           "instead of ratio: height of the first layer"));
  b.push_back(params::reals("ratio_line", &BoundaryLayerConfig::ratio_line, "",
                            "[xa, ya, za, xb, yb, zb]: the ratio varies linearly from A to B (with ratio_end)"));
  b.push_back(params::real("ratio_end", &BoundaryLayerConfig::ratio_end, ">= 1", "the ratio at B of ratio_line"));
  b.push_back(params::real("y_plus", &BoundaryLayerConfig::y_plus, "> 0",
                           "instead of ratio or first_cell_height: the first cell's y+ (with reynolds)"));
  b.push_back(params::real("reynolds", &BoundaryLayerConfig::reynolds, "> 0",
                           "Reynolds number based on reference_length, for y_plus"));
  b.push_back(params::real("reference_length", &BoundaryLayerConfig::reference_length, "> 0",
                           "length the Reynolds number is based on; unset: the chord"));
  params::Table<Config> table;
  append(table, &Config::boundary_layer, b);
  return table;
}

params::Table<Config> wall_layer_keys() {
  params::Table<WallLayerConfig> w = {
      params::real("thickness", &WallLayerConfig::thickness, ">= 0",
                   "C: the wall layer's thickness δ_wall, model units; 0: a slip wall (no wall layer, the O-type root)"),
  };
  append(w, &WallLayerConfig::split, ho::layer_keys());
  w.push_back(params::real("first_cell_height", &WallLayerConfig::first_cell_height, "> 0",
                           "instead of ratio: height of the first wall layer"));
  w.push_back(params::reals("ratio_line", &WallLayerConfig::ratio_line, "",
                            "[xa, ya, za, xb, yb, zb]: the wall ratio varies linearly from A to B (with ratio_end)"));
  w.push_back(params::real("ratio_end", &WallLayerConfig::ratio_end, ">= 1", "the wall ratio at B of ratio_line"));
  params::Table<Config> table;
  append(table, &Config::wall_layer, w);
  return table;
}

params::Table<Config> sizing_keys() {
  params::Table<SizingConfig> z;
  append(z, &SizingConfig::size, surface::size_keys());
  z.push_back(params::integer("chordwise", &SizingConfig::chordwise, ">= 0",
                              "segments on each root/tip section curve (NACA curve names); 0: from the size field"));
  z.push_back(params::integer("spanwise", &SizingConfig::spanwise, ">= 0",
                              "segments on each spanwise edge (NACA curve names); 0: from the size field"));
  params::Table<Config> table;
  append(table, &Config::sizing, z);
  return table;
}

params::Table<Config> output_keys() {
  std::vector<std::string> names;
  for (const OutputFormat& f : output_formats()) names.push_back(f.name);
  params::Table<OutputConfig> o = {
      params::strings("formats", &OutputConfig::formats, "each of " + params::choice_range(names),
                      "mesh files to write, each format at most once"),
      params::choice("target", &OutputConfig::target, {{"any", OutputTarget::Any}, {"pyfr", OutputTarget::Pyfr}},
                     "\"pyfr\": meet PyFR's importer (pyramids only on parallelogram bases: H-type, the layer "
                     "edges over each side's trailing edge made one vector; the hex columns under the others split "
                     "into prisms, their end pyramids into tetrahedra; order <= 4; an ASCII MSH format); \"any\": "
                     "the near field as built"),
      params::string("directory", &OutputConfig::directory, "non-empty", "where the files go (created if needed)"),
      params::string("basename", &OutputConfig::basename, "non-empty", "mesh file names, without folder"),
      params::boolean("allow_invalid", &OutputConfig::allow_invalid, "write the mesh even when a check fails"),
      params::boolean("pictures", &OutputConfig::pictures,
                      "SVG pictures beside the mesh: spanwise cuts, the body's surface mesh, a quality histogram"),
      params::real("picture_station", &OutputConfig::picture_station, "(0, 1)",
                   "where the spanwise cut of the pictures is, as a fraction of the span"),
  };
  params::Table<Config> table;
  append(table, &Config::output, o);
  return table;
}

params::Table<Config> checks_keys() {
  params::Table<ChecksConfig> k = {
      params::real("min_scaled_jacobian", &ChecksConfig::min_scaled_jacobian, "[0, 1)",
                   "an element counts as invalid unless proven valid with a certified scaled Jacobian of at "
                   "least this; 0: proven validity only"),
      params::boolean("inherit_bounds", &ChecksConfig::inherit_bounds,
                      "a split element's pieces take the det J bounds of their coarse element restricted to "
                      "them; false: certify every element on its own nodes (the reference, slower)"),
  };
  params::Table<Config> table;
  append(table, &Config::checks, k);
  return table;
}

template <class P>
params::Table<Config> stage_keys(P Config::*member, const params::Table<P>& keys) {
  params::Table<Config> table;
  append(table, member, keys);
  return table;
}

}  // namespace

const std::vector<ConfigSection>& config_sections() {
  static const std::vector<ConfigSection> sections = {
      {"geometry", geometry_keys()},
      {"geometry.naca", naca_keys()},
      {"geometry.wall_plane", wall_plane_keys()},
      {"geometry.join", join_keys()},
      {"geometry.body_cut", body_cut_keys()},
      {"geometry.farfield", farfield_shape_keys(), true, true},
      {"geometry.farfield.sphere", farfield_sphere_keys()},
      {"nearfield", nearfield_keys()},
      {"boundary_layer", boundary_layer_keys()},
      {"wall_layer", wall_layer_keys()},
      {"wake", stage_keys(&Config::wake, nearfield::wake_keys())},
      {"sizing", sizing_keys()},
      {"farfield", stage_keys(&Config::farfield, farfield::far_field_keys())},
      {"highorder", stage_keys(&Config::highorder, ho::curving_keys())},
      {"checks", checks_keys()},
      {"output", output_keys()},
  };
  return sections;
}

}  // namespace semimesh::pipeline
