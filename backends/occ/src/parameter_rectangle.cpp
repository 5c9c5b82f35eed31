#include "parameter_rectangle.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>

#include <cmath>

namespace semimesh::occ {

double surface_area(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props);
  return props.Mass();
}

bool is_parameter_rectangle(const TopoDS_Face& face, double tolerance) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const BRepBuilderAPI_MakeFace whole(BRep_Tool::Surface(face), u0, u1, v0, v1, tolerance);
  const double area = surface_area(face);
  return whole.IsDone() && std::abs(surface_area(whole.Face()) - area) <= 1e-6 * area;
}

}  // namespace semimesh::occ
