#include "occ_surface.hpp"
#include "span_cache.hpp"
#include "to_vec.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom2d_Curve.hxx>
#include <Precision.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <ShapeAnalysis_Edge.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <optional>
#include <vector>

namespace semimesh::occ {
namespace {

// Planar by geometry, whatever the surface's type: within 1e-7 of the face's bounding-box diagonal
// over the parameter box (the trimmed face lies inside it).
bool lies_in_a_plane(const Handle(Geom_Surface)& surface, const TopoDS_Face& face, const std::array<cad::Interval, 2>& box) {
  constexpr double kRelativeTolerance = 1e-7;
  Bnd_Box extent;
  BRepBndLib::Add(face, extent);
  if (extent.IsVoid()) return false;
  const double size = std::sqrt(extent.SquareExtent());
  if (!(size > 0.0)) return false;
  try {
    const Handle(Geom_Surface) patch =
        new Geom_RectangularTrimmedSurface(surface, box[0].lo, box[0].hi, box[1].lo, box[1].hi);
    return GeomLib_IsPlanarSurface(patch, kRelativeTolerance * size).IsPlanar();
  } catch (const Standard_Failure&) {
    // A parameter box OCC will not trim to (e.g. past a periodic surface's period): the whole
    // surface must be a plane then.
  }
  try {
    return GeomLib_IsPlanarSurface(surface, kRelativeTolerance * size).IsPlanar();
  } catch (const Standard_Failure&) {
    return false;  // OCC cannot tell: not planar, as by type
  }
}

cad::SurfaceKind kind_of(GeomAbs_SurfaceType type) {
  switch (type) {
    case GeomAbs_Plane: return cad::SurfaceKind::Plane;
    case GeomAbs_Cylinder: return cad::SurfaceKind::Cylinder;
    case GeomAbs_Cone: return cad::SurfaceKind::Cone;
    case GeomAbs_Sphere: return cad::SurfaceKind::Sphere;
    case GeomAbs_Torus: return cad::SurfaceKind::Torus;
    case GeomAbs_BezierSurface: return cad::SurfaceKind::Bezier;
    case GeomAbs_BSplineSurface: return cad::SurfaceKind::BSpline;
    case GeomAbs_SurfaceOfRevolution: return cad::SurfaceKind::Revolution;
    case GeomAbs_SurfaceOfExtrusion: return cad::SurfaceKind::Extrusion;
    case GeomAbs_OffsetSurface: return cad::SurfaceKind::Offset;
    default: return cad::SurfaceKind::Other;
  }
}

/// Grid nodes along u (or v): a few per polynomial span so that every bump of a B-spline is seen,
/// never fewer than a coarse default nor so many that a query scans a large grid.
int samples_along(const GeomAdaptor_Surface& box, bool along_u) {
  constexpr int kPerSpan = 3, kMin = 25, kMax = 65;
  int spans = 1;
  try {
    spans = along_u ? box.NbUIntervals(GeomAbs_C2) : box.NbVIntervals(GeomAbs_C2);
  } catch (const Standard_Failure&) {
    // not split into intervals: the default count
  }
  return std::clamp(kPerSpan * spans + 1, kMin, kMax);
}

/// A length covering the face's tolerance, its edges' tolerances and, twice over, the largest
/// measured gap between an edge's 3D curve and its pcurve on the face.
double boundary_tolerance(const TopoDS_Face& face) {
  double tolerance = BRep_Tool::Tolerance(face);
  ShapeAnalysis_Edge check;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(edge));
    double deviation = 0.0;  // measured even when the check fails (a deviation above tolerance)
    if (!BRep_Tool::Degenerated(edge)) check.CheckSameParameter(edge, face, deviation);
    tolerance = std::max(tolerance, 2.0 * deviation);

  }
  return tolerance;
}

/// Ranking of unguided projection results: converged and inside the trimmed face first, then
/// converged, then the rest; nearest first within each group.
bool preferred(const cad::SurfaceProjection& a, const cad::SurfaceProjection& b) {
  const auto group = [](const cad::SurfaceProjection& p) { return p.converged ? (p.inside ? 0 : 1) : 2; };
  if (group(a) != group(b)) return group(a) < group(b);
  return a.distance < b.distance;
}

// OCC's period of a periodic parameter; for a closed, non-periodic one the length of the range.
// Found once: a B-spline's IsUClosed builds its two boundary iso-curves at every call (a surface
// mesh's edge swaps asked it millions of times on an OpenVSP wing: 90 % of 216 s).
std::optional<double> period_of(const Handle(Geom_Surface)& surface, bool along_u) {
  if (along_u ? surface->IsUPeriodic() : surface->IsVPeriodic()) return along_u ? surface->UPeriod() : surface->VPeriod();
  if (!(along_u ? surface->IsUClosed() : surface->IsVClosed())) return std::nullopt;
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  const double length = along_u ? u1 - u0 : v1 - v0;
  if (!std::isfinite(length) || !(length > 0.0)) return std::nullopt;
  return length;
}

}  // namespace

OccSurface::OccSurface(int id, std::string name, const TopoDS_Face& fluid_face)
    : cad::Surface(id, std::move(name), fluid_face.Orientation() == TopAbs_REVERSED ? -1 : +1),
      face_(TopoDS::Face(fluid_face.Oriented(TopAbs_FORWARD))) {
  surface_ = BRep_Tool::Surface(face_);  // location already applied
  if (surface_.IsNull())
    throw cad::CadError(cad::CadError::Kind::Geometry, "occ: face of surface " + std::to_string(id) + " has no surface");
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face_, u0, u1, v0, v1);
  bounds_ = {cad::Interval{u0, u1}, cad::Interval{v0, v1}};
  GeomAdaptor_Surface box_adaptor(surface_, u0, u1, v0, v1);
  // The stricter of the two parameter directions, so no point much further than the tolerance
  // from a trimming curve counts as on it.
  const double tolerance = boundary_tolerance(face_);
  uv_tolerance_ = std::min(box_adaptor.UResolution(tolerance), box_adaptor.VResolution(tolerance));
  GeomAbs_SurfaceType type = box_adaptor.GetType();
  kind_ = kind_of(type);
  planar_ = kind_ == cad::SurfaceKind::Plane || lies_in_a_plane(surface_, face_, bounds_);
  span_cached_ = type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface;
  serial_ = new_surface_serial();
  mutable_evaluator_ = type == GeomAbs_SurfaceOfRevolution || type == GeomAbs_SurfaceOfExtrusion ||
                       type == GeomAbs_OffsetSurface;
  grid_ = std::make_unique<SampleGrid>(bounds_, samples_along(box_adaptor, true), samples_along(box_adaptor, false),
                                       [this](const cad::Vec2& uv) { return point(uv); });
  periods_ = {period_of(surface_, true), period_of(surface_, false)};
}

const Handle(Geom_Surface)& OccSurface::evaluated_surface() const {
  return mutable_evaluator_ ? thread_copy(serial_, surface_) : surface_;
}

cad::SurfaceDerivatives OccSurface::derivatives_shared(const cad::Vec2& uv) const {
  gp_Pnt p;
  gp_Vec du, dv, duu, dvv, duv;
  surface_->D2(uv.x(), uv.y(), p, du, dv, duu, dvv, duv);
  return {to_vec(p.XYZ()), to_vec(du.XYZ()), to_vec(dv.XYZ()), to_vec(duu.XYZ()), to_vec(duv.XYZ()), to_vec(dvv.XYZ())};
}

cad::SurfaceDerivatives OccSurface::derivatives(const cad::Vec2& uv) const {
  gp_Pnt p;
  gp_Vec du, dv, duu, dvv, duv;
  if (span_cached_)
    thread_adaptor(serial_, surface_).D2(uv.x(), uv.y(), p, du, dv, duu, dvv, duv);
  else
    evaluated_surface()->D2(uv.x(), uv.y(), p, du, dv, duu, dvv, duv);
  return {to_vec(p.XYZ()), to_vec(du.XYZ()), to_vec(dv.XYZ()), to_vec(duu.XYZ()), to_vec(duv.XYZ()), to_vec(dvv.XYZ())};
}

std::optional<double> OccSurface::period(int direction) const {
  cad::Surface::period(direction);  // checks the direction
  return periods_[direction];
}

std::optional<double> OccSurface::exact_area() const {
  try {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face_, props);
    return props.Mass();
  } catch (const Standard_Failure&) {
    return std::nullopt;  // OCC gave up: the generic quadrature answers
  }
}

namespace {

// What the exact classifier (BRepTopAdaptor_FClass2d with the face's tolerance, then
// BRepClass_FaceClassifier) may count as on the boundary, in the parameters: within `boundary` of
// a pcurve (the raster's own margin), within a vertex's tolerance of it (the larger of its u and
// v resolutions, as BRepClass_Intersector takes them), and surely within the face's tolerance of a
// pcurve (CheckOn: never refined below Precision::Confusion()).
TrimRaster::Tolerances classifier_tolerances(const TopoDS_Face& face, double boundary) {
  const BRepAdaptor_Surface surface(face, false);
  double vertex = boundary;
  for (TopExp_Explorer v(face, TopAbs_VERTEX); v.More(); v.Next()) {
    const double tolerance = BRep_Tool::Tolerance(TopoDS::Vertex(v.Current()));
    vertex = std::max({vertex, surface.UResolution(tolerance), surface.VResolution(tolerance)});
  }
  return {boundary, vertex, std::min(BRep_Tool::Tolerance(face), Precision::Confusion())};
}

}  // namespace

BRepTopAdaptor_FClass2d& OccSurface::thread_classifier(bool tolerant) const {
  // Classifiers of faces whose model is gone stay until the map is this full, then all go.
  constexpr std::size_t kMaxFacesPerThread = 4096;
  thread_local std::unordered_map<std::uint64_t, std::array<std::unique_ptr<BRepTopAdaptor_FClass2d>, 2>> classifiers;
  if (classifiers.size() >= kMaxFacesPerThread && classifiers.find(serial_) == classifiers.end()) classifiers.clear();
  std::unique_ptr<BRepTopAdaptor_FClass2d>& slot = classifiers[serial_][tolerant ? 1 : 0];
  if (!slot) slot = std::make_unique<BRepTopAdaptor_FClass2d>(face_, tolerant ? uv_tolerance_ : BRep_Tool::Tolerance(face_));
  return *slot;
}

bool OccSurface::contains_exactly(const cad::Vec2& uv) const {
  const TopAbs_State state = thread_classifier(false).Perform(gp_Pnt2d(uv.x(), uv.y()));
  return state == TopAbs_IN || state == TopAbs_ON;
}

bool OccSurface::contains(const cad::Vec2& uv) const {
  if (const TrimRaster* raster = trim_raster())
    if (const std::optional<bool> known = raster->lookup(uv)) return *known;
  return contains_exactly(uv);
}

bool OccSurface::within_tolerance_of_face(const cad::Vec2& uv) const {
  if (const TrimRaster* raster = trim_raster())
    if (const std::optional<bool> known = raster->lookup(uv)) return *known;
  const TopAbs_State state = thread_classifier(true).Perform(gp_Pnt2d(uv.x(), uv.y()));
  return state == TopAbs_IN || state == TopAbs_ON;
}

const TrimRaster* OccSurface::trim_raster() const {
  std::call_once(raster_built_, [this] {
    constexpr int kCells = 256, kSubCells = 8;
    // Points of every pcurve of the face's loops, refined until consecutive ones are at most half
    // a cell apart along u and v; a loop that will not refine (or has no pcurve) leaves no raster.
    auto raster = std::make_unique<TrimRaster>(bounds_, kCells);
    const cad::Vec2 cell = raster->cell_size();
    const double tolerance = std::max(uv_tolerance_, BRep_Tool::Tolerance(face_));
    const auto margin_for = [&](const cad::Vec2& size) {
      return 2 + static_cast<int>(std::ceil(tolerance / std::min(size.x(), size.y())));
    };
    const int margin = margin_for(cell);
    if (margin > kCells / 8) return;
    std::vector<std::vector<cad::Vec2>> fine_loops;  // the same at half a sub-cell, for refine()
    std::vector<std::vector<cad::Vec2>> fine_midpoints;  // halfway in parameter between fine samples
    bool refinable = margin_for(cell / kSubCells) <= kSubCells;
    for (TopExp_Explorer e(face_, TopAbs_EDGE); e.More(); e.Next()) {
      double first, last;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face_, first, last);
      if (pcurve.IsNull() || !std::isfinite(first) || !std::isfinite(last)) return;
      const auto sampled = [&](const cad::Vec2& size, int count, int most) -> std::optional<std::vector<cad::Vec2>> {
        std::vector<cad::Vec2> samples;
        for (;; count *= 2) {
          if (count > most) return std::nullopt;
          samples.clear();
          bool fine = true;
          for (int k = 0; k <= count; ++k) {
            const gp_Pnt2d p = pcurve->Value(first + (last - first) * k / count);
            samples.emplace_back(p.X(), p.Y());
            if (k > 0) {
              const cad::Vec2 step = (samples[k] - samples[k - 1]).cwiseAbs();
              fine = fine && step.x() <= 0.5 * size.x() && step.y() <= 0.5 * size.y();
            }
          }
          if (fine) return samples;
        }
      };
      const std::optional<std::vector<cad::Vec2>> samples = sampled(cell, 16, 1 << 16);
      if (!samples) return;
      raster->mark_loop(*samples, margin);
      if (refinable) {
        std::optional<std::vector<cad::Vec2>> fine = sampled(cell / kSubCells, static_cast<int>(samples->size() - 1) * kSubCells, 1 << 18);
        refinable = fine.has_value();
        if (fine) {
          const double count = static_cast<double>(fine->size() - 1);
          std::vector<cad::Vec2> midpoints;
          for (std::size_t k = 0; k + 1 < fine->size(); ++k) {
            const gp_Pnt2d p = pcurve->Value(first + (last - first) * (static_cast<double>(k) + 0.5) / count);
            midpoints.emplace_back(p.X(), p.Y());
          }
          fine_loops.push_back(std::move(*fine));
          fine_midpoints.push_back(std::move(midpoints));
        }
      }
    }
    const auto exact = [this](const cad::Vec2& uv) { return contains_exactly(uv); };
    raster->classify(exact);
    if (refinable && raster->refine(kSubCells, fine_loops, margin_for(cell / kSubCells), exact))
      raster->keep_polylines(fine_loops, fine_midpoints, classifier_tolerances(face_, tolerance));
    raster_ = std::move(raster);
  });
  return raster_.get();
}

cad::SurfaceProjection OccSurface::project(const cad::Vec3& x, std::optional<cad::Vec2> guess) const {
  if (guess) return cad::Surface::project(x, guess);
  std::optional<cad::SurfaceProjection> best;
  const auto settled = [&] { return best && best->inside && best->converged; };
  const auto start_from = [&](const cad::Vec2& uv) {
    cad::SurfaceProjection p = cad::Surface::project(x, uv);
    p.inside = p.inside || within_tolerance_of_face(p.uv);
    if (!best || preferred(p, *best)) best = p;
  };
  for (const GridSeed& seed : grid_->local_minima(x, kGridSeeds)) {
    if (settled() && seed.distance - grid_->cell_reach() > best->distance) break;  // nearest first
    start_from(seed.uv);
  }
  if (!settled())
    for (const cad::Vec2& uv : extremum_starts(x)) start_from(uv);
  if (!best) start_from(cad::Vec2(0.5 * (bounds_[0].lo + bounds_[0].hi), 0.5 * (bounds_[1].lo + bounds_[1].hi)));
  return *best;
}

std::vector<cad::Vec2> OccSurface::extremum_starts(const cad::Vec3& x) const {
  std::optional<cad::Vec2> best_inside, best_any;
  double d_inside = std::numeric_limits<double>::max(), d_any = d_inside;
  try {
    GeomAPI_ProjectPointOnSurf extrema(gp_Pnt(x.x(), x.y(), x.z()), evaluated_surface(), bounds_[0].lo, bounds_[0].hi,
                                       bounds_[1].lo, bounds_[1].hi);
    for (int i = 1; i <= extrema.NbPoints(); ++i) {
      double u, v;
      extrema.Parameters(i, u, v);
      const double d = extrema.Distance(i);
      const cad::Vec2 uv(u, v);
      if (d < d_any) { d_any = d; best_any = uv; }
      if (d < d_inside && contains(uv)) { d_inside = d; best_inside = uv; }
    }
  } catch (const Standard_Failure&) {
    // OCC gave up (e.g. at a singular point): the grid's starts stand alone.
  }
  std::vector<cad::Vec2> starts;
  if (best_inside) starts.push_back(*best_inside);
  if (best_any && best_any != best_inside) starts.push_back(*best_any);
  return starts;
}

}  // namespace semimesh::occ
