// Areas and volumes of OCC shapes for the occ tests, by OCCT's adaptive integration (to 1e-10
// relative: thin bodies and sharp leading edges need it).
#pragma once

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS_Shape.hxx>

namespace semimesh::occ::test {

inline double area_of(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props, 1e-10);
  return props.Mass();
}

inline double volume_of(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-10);
  return props.Mass();
}

}  // namespace semimesh::occ::test
