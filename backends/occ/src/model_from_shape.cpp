// Shape -> cadapi Model: unique faces, edges and vertices (TopTools_IndexedMapOfShape), each face
// oriented towards the fluid, loops walked with the material on the left seen from the fluid.
#include "occ_curve.hpp"
#include "occ_surface.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <NCollection_DataMap.hxx>
#include <ShapeAnalysis_ShapeTolerance.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Solid.hxx>

#include <set>

namespace semimesh::occ {
namespace {

using FaceOrientations = NCollection_DataMap<TopoDS_Shape, TopAbs_Orientation, TopTools_ShapeMapHasher>;

/// Whether every non-degenerated edge of `shell` bounds two face uses (a seam counts twice).
bool is_closed_shell(const TopoDS_Shape& shell) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    int uses = edge_faces.FindFromIndex(i).Extent();
    if (uses == 1 && BRep_Tool::IsClosed(edge, TopoDS::Face(edge_faces.FindFromIndex(i).First()))) uses = 2;
    if (uses != 2) return false;
  }
  return edge_faces.Extent() > 0;
}

/// Records, for each face of `oriented`, the orientation whose normal points into the fluid.
void record(const TopoDS_Shape& oriented, bool reverse, FaceOrientations& out) {
  for (TopExp_Explorer f(oriented, TopAbs_FACE); f.More(); f.Next()) {
    TopAbs_Orientation o = f.Current().Orientation();
    if (!out.IsBound(f.Current())) out.Bind(f.Current(), reverse ? TopAbs::Reverse(o) : o);
  }
}

/// Whether a solid's faces point into it (negative volume): it encloses the infinite rest of space.
bool inside_out(const TopoDS_Shape& solid) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  return props.Mass() < 0.0;
}

/// The fluid-side orientation of every face (see FluidSide). Solids and closed shells are taken
/// with the orientation that encloses a finite volume, so their face normals point out of it.
FaceOrientations fluid_orientations(const TopoDS_Shape& shape, FluidSide side) {
  FaceOrientations out;
  for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next())
    record(s.Current(), (side == FluidSide::Inside) != inside_out(s.Current()), out);
  for (TopExp_Explorer s(shape, TopAbs_SHELL, TopAbs_SOLID); s.More(); s.Next()) {
    if (!is_closed_shell(s.Current())) continue;
    TopoDS_Solid solid;
    BRep_Builder builder;
    builder.MakeSolid(solid);
    builder.Add(solid, s.Current());
    record(solid, (side != FluidSide::Outside) != inside_out(solid), out);
  }
  record(shape, false, out);  // open shells and free faces: as stored
  return out;
}

using ShapeNames = NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher>;

ShapeNames name_map(const std::vector<std::pair<TopoDS_Shape, std::string>>& names) {
  ShapeNames out;
  for (const auto& [shape, name] : names)
    if (!out.IsBound(shape)) out.Bind(shape, name);
  return out;
}

/// The given name of `shape`, or "<prefix>_<id>" when it has none (or "NONE"); a name already
/// `taken` gets "_<id>" appended.
std::string unique_name(const ShapeNames& given, const TopoDS_Shape& shape, const std::string& prefix, int id,
                        std::set<std::string>& taken) {
  std::string name = given.IsBound(shape) ? given.Find(shape) : std::string();
  if (name.empty() || name == "NONE") name = prefix + "_" + std::to_string(id);
  if (taken.count(name)) name += "_" + std::to_string(id);
  taken.insert(name);
  return name;
}

}  // namespace

std::unique_ptr<cad::Model> model_from_shape(const TopoDS_Shape& shape, const std::string& backend_label,
                                             const ModelOptions& options) {
  TopTools_IndexedMapOfShape faces, edges, vertices;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  if (faces.IsEmpty())
    throw cad::CadError(cad::CadError::Kind::NoGeometry, "backend '" + backend_label + "': the shape has no faces");

  auto model = std::make_unique<cad::Model>(backend_label);
  model->keep_alive(std::make_shared<TopoDS_Shape>(shape));
  bool thread_safe = true;

  for (int i = 1; i <= vertices.Extent(); ++i) {
    gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
    model->add_vertex(cad::Vec3(p.X(), p.Y(), p.Z()));
  }

  const ShapeNames edge_names = name_map(options.edge_names);
  std::set<std::string> curve_names_taken;
  std::vector<int> curve_of_edge(edges.Extent() + 1, -1);  // map index -> curve id
  for (int i = 1; i <= edges.Extent(); ++i) {
    TopoDS_Edge edge = TopoDS::Edge(edges(i).Oriented(TopAbs_FORWARD));
    const int id = model->num_curves();
    auto curve = std::make_unique<OccCurve>(id, unique_name(edge_names, edges(i), "edge", id, curve_names_taken), edge);
    thread_safe = thread_safe && !curve->has_mutable_evaluator();
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    if (first.IsNull() || last.IsNull())
      throw cad::CadError(cad::CadError::Kind::Geometry,
                          "backend '" + backend_label + "': edge " + std::to_string(id) + " has no end vertex");
    model->add_curve(std::move(curve), vertices.FindIndex(first) - 1, vertices.FindIndex(last) - 1);
    curve_of_edge[i] = id;
  }

  const FaceOrientations fluid = fluid_orientations(shape, options.fluid_side);
  const ShapeNames face_names = name_map(options.face_names);
  std::set<std::string> surface_names_taken;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const int id = i - 1;
    TopoDS_Face face = TopoDS::Face(faces(i).Oriented(fluid.Find(faces(i))));
    std::vector<cad::Loop> loops;
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    auto add_loop = [&](const TopoDS_Wire& wire) {
      cad::Loop loop;
      for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
        const TopoDS_Edge& edge = e.Current();
        const int curve = curve_of_edge[edges.FindIndex(edge)];
        if (edge.Orientation() != TopAbs_FORWARD && edge.Orientation() != TopAbs_REVERSED) continue;  // internal
        loop.uses.push_back(cad::CurveUse{curve, edge.Orientation() == TopAbs_FORWARD});
      }
      if (!loop.uses.empty()) loops.push_back(std::move(loop));
    };
    if (!outer.IsNull()) add_loop(outer);
    for (TopoDS_Iterator w(face); w.More(); w.Next())
      if (w.Value().ShapeType() == TopAbs_WIRE && !w.Value().IsSame(outer)) add_loop(TopoDS::Wire(w.Value()));
    auto surface = std::make_unique<OccSurface>(id, unique_name(face_names, faces(i), "face", id, surface_names_taken), face);
    model->add_surface(std::move(surface), std::move(loops));
  }

  model->set_units(options.units, options.scale_applied);
  model->set_units_origin(options.units_origin);
  for (const std::string& repair : options.repairs) model->add_repair(repair);
  model->set_tolerance(ShapeAnalysis_ShapeTolerance().Tolerance(shape, 1));  // 1: the largest
  model->set_thread_safe(thread_safe);
  model->finalize();
  return model;
}

}  // namespace semimesh::occ
