#include "semimesh/cad/types.hpp"

namespace semimesh::cad {

std::string to_string(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Plane: return "plane";
    case SurfaceKind::Cylinder: return "cylinder";
    case SurfaceKind::Cone: return "cone";
    case SurfaceKind::Sphere: return "sphere";
    case SurfaceKind::Torus: return "torus";
    case SurfaceKind::BSpline: return "bspline";
    case SurfaceKind::Bezier: return "bezier";
    case SurfaceKind::Revolution: return "revolution";
    case SurfaceKind::Extrusion: return "extrusion";
    case SurfaceKind::Offset: return "offset";
    case SurfaceKind::Analytic: return "analytic";
    case SurfaceKind::Other: return "other";
  }
  return "other";
}

std::string to_string(CurveKind kind) {
  switch (kind) {
    case CurveKind::Line: return "line";
    case CurveKind::Circle: return "circle";
    case CurveKind::Ellipse: return "ellipse";
    case CurveKind::BSpline: return "bspline";
    case CurveKind::Bezier: return "bezier";
    case CurveKind::Analytic: return "analytic";
    case CurveKind::Other: return "other";
  }
  return "other";
}

}  // namespace semimesh::cad
