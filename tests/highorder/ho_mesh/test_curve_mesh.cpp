// CAD curving on the analytic NACA 0012 wing: a prism layer extruded from a structured mesh of the
// `upper` surface, curved at P = 2..4; nodes on the CAD, geometric error convergence, validity.
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/mesh/node_layout.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/surface/surface_mesh.hpp"
#ifdef SEMIMESH_HAVE_OCC
#include "semimesh/occ/occ_backend.hpp"
#endif

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <cstdio>
#include <memory>
#include <vector>

namespace semimesh::ho {
namespace {

struct Wing {
  std::unique_ptr<cad::Model> model;
  int upper = -1;
};

const Wing& wing() {
  static const Wing w = [] {
    mock_cad::NacaWingParams p;
    p.farfield = false;
    Wing out{mock_cad::make_naca_wing(p), -1};
    out.upper = *out.model->find_surface("upper");
    return out;
  }();
  return w;
}

// One layer of prisms of thickness `thickness` over a chordwise x spanwise structured triangle mesh
// of the `upper` surface of `model` (chordwise nodes clustered at both ends by a cosine law when
// `cluster`); body vertices carry their CAD attachment, skin vertices none; the body triangles form
// the group "wing"; prisms alternate between the regions "wing_layer" and "junction" (so region
// bookkeeping is visible). Spanwise curves (LE, TE) are told from chordwise ones by their end points.
mesh::Mesh upper_layer(const cad::Model& model, int chordwise, int spanwise, double thickness, bool cluster) {
  const int upper = *model.find_surface("upper");
  std::vector<surface::CurveMesh> curves;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto ends = model.curve_vertices(c);
    const Eigen::Vector3d d = model.vertex(ends[1]).point - model.vertex(ends[0]).point;
    const bool spanwise_curve = std::abs(d.z()) > std::abs(d.x());
    surface::CurveCount count{spanwise_curve ? spanwise : chordwise, {}};
    if (!spanwise_curve && cluster) count.bunching.law = surface::Bunching::Law::Cosine;
    curves.push_back(surface::discretise_curve(model, c, count));
  }
  const surface::SurfaceMesh sm = surface::mesh_surface_structured(model, upper, surface::CurveMeshes(curves), true);
  const cad::Surface& s = model.surface(upper);
  mesh::Mesh m(1);
  const int n = sm.num_nodes();
  for (int i = 0; i < n; ++i) {
    mesh::CadAttachment a;
    if (sm.origin[i].vertex >= 0)
      a = {mesh::CadAttachment::Vertex, sm.origin[i].vertex, 0, 0};
    else if (sm.origin[i].on_boundary())
      a = {mesh::CadAttachment::Curve, sm.origin[i].curve, sm.origin[i].t, 0};
    else
      a = {mesh::CadAttachment::Surface, upper, sm.uv[i](0), sm.uv[i](1)};
    m.add_node(sm.points[i], a);
  }
  for (int i = 0; i < n; ++i) m.add_node(sm.points[i] + thickness * s.normal(sm.uv[i]));
  const int regions[2] = {m.region_index("wing_layer"), m.region_index("junction")};
  for (std::size_t k = 0; k < sm.triangles.size(); ++k) {
    const auto& t = sm.triangles[k];
    const auto a = mesh::NodeId(t[0]), b = mesh::NodeId(t[1]), c = mesh::NodeId(t[2]);
    m.add_element(Shape::Prism, {a, b, c, a + n, b + n, c + n}, regions[k % 2]);
    m.add_boundary_face("wing", Shape::Triangle, {a, c, b});
  }
  return m;
}

mesh::Mesh upper_layer(int chordwise, int spanwise, double thickness, bool cluster) {
  return upper_layer(*wing().model, chordwise, spanwise, thickness, cluster);
}

double distance_to_upper(const Eigen::Vector3d& x) {
  return wing().model->surface(wing().upper).project(x).distance;
}

TEST(CurveMesh, BoundaryNodesLieOnTheCad) {
  const mesh::Mesh linear = upper_layer(6, 2, 0.02, true);
  for (int P = 2; P <= 4; ++P)
    for (NodePlacement placement : {NodePlacement::Parameter, NodePlacement::Springs}) {
      CurvingStats stats;
      const mesh::Mesh curved = curve_mesh(linear, *wing().model, {P, NodeSet::GLL, 50, 1e-10, placement}, &stats);
      EXPECT_EQ(curved.order(), P);
      EXPECT_EQ(curved.elements().size(), linear.elements().size());
      EXPECT_EQ(stats.edges_on_curves, 2 * 6 + 2 * 2);  // root, tip chordwise; LE, TE spanwise
      EXPECT_GT(stats.edges_on_surfaces, 0);
      EXPECT_EQ(stats.faces_on_surfaces, P >= 3 ? int(linear.boundary_faces().size()) : 0);
      EXPECT_EQ(stats.optimisation_fallbacks, 0);
      EXPECT_GT(stats.max_projection_distance, 1e-4);  // the straight sides really were moved
      double worst = 0.0;
      for (std::size_t b = 0; b < curved.boundary_faces().size(); ++b)
        for (mesh::NodeId id : curved.boundary_face_nodes(b)) {
          worst = std::max(worst, distance_to_upper(curved.node(id)));
          const mesh::CadAttachment& a = curved.cad_attachment(id);
          ASSERT_NE(a.kind, mesh::CadAttachment::None) << "node " << id << " at P = " << P;
          if (a.kind == mesh::CadAttachment::Surface) {
            EXPECT_LT((wing().model->surface(a.entity).point({a.u, a.v}) - curved.node(id)).norm(), 1e-12);
          }
        }
      EXPECT_LT(worst, 1e-9) << "P = " << P;
    }
}

TEST(CurveMesh, ElementsKeepTheirRegion) {
  const mesh::Mesh linear = upper_layer(6, 2, 0.02, false);
  const mesh::Mesh curved = curve_mesh(linear, *wing().model, {3, NodeSet::GLL, 50, 1e-10});
  ASSERT_EQ(curved.region_names(), linear.region_names());
  ASSERT_EQ(curved.elements().size(), linear.elements().size());
  for (std::size_t e = 0; e < linear.elements().size(); ++e)
    EXPECT_EQ(curved.elements()[e].region, linear.elements()[e].region) << "element " << e;
}

// The curved mesh takes the linear one's edges and faces (Mesh::adopt_entities, add_element_as):
// the mesh add_element builds from the same nodes and node lists, entity for entity (ids,
// vertices, orientations, the nodes each owns), orders 1-4.
TEST(CurveMesh, AdoptedEntitiesAreTheOnesAddElementBuilds) {
  const mesh::Mesh linear = upper_layer(6, 3, 0.02, true);
  for (int P = 1; P <= 4; ++P) {
    SCOPED_TRACE("P = " + std::to_string(P));
    const mesh::Mesh curved = curve_mesh(linear, *wing().model, {P, NodeSet::GLL, 50, 1e-10});
    mesh::Mesh built(P, NodeSet::GLL);
    for (mesh::NodeId v = 0; v < curved.num_nodes(); ++v) built.add_node(curved.node(v), curved.cad_attachment(v));
    built.copy_regions_from(curved);
    built.add_elements_of(curved, 0, curved.elements().size());
    ASSERT_EQ(curved.edges().size(), built.edges().size());
    ASSERT_EQ(curved.faces().size(), built.faces().size());
    for (std::size_t e = 0; e < curved.edges().size(); ++e) {
      EXPECT_EQ(curved.edges()[e].vertices, built.edges()[e].vertices);
      EXPECT_EQ(curved.edge_nodes(e), built.edge_nodes(e)) << "edge " << e;
      EXPECT_EQ(curved.find_edge(curved.edges()[e].vertices[1], curved.edges()[e].vertices[0]), static_cast<long>(e));
    }
    for (std::size_t f = 0; f < curved.faces().size(); ++f) {
      EXPECT_EQ(curved.faces()[f].vertices, built.faces()[f].vertices);
      EXPECT_EQ(curved.faces()[f].edges, built.faces()[f].edges);
      EXPECT_EQ(curved.faces()[f].edge_reversed, built.faces()[f].edge_reversed);
      EXPECT_EQ(curved.face_nodes(f), built.face_nodes(f)) << "face " << f;
    }
    for (std::size_t e = 0; e < curved.elements().size(); ++e) {
      const mesh::Element &a = curved.elements()[e], &b = built.elements()[e];
      EXPECT_EQ(a.edges, b.edges);
      EXPECT_EQ(a.edge_reversed, b.edge_reversed);
      EXPECT_EQ(a.faces, b.faces);
      EXPECT_EQ(a.face_orientation, b.face_orientation);
      EXPECT_EQ(a.region, b.region);
      EXPECT_EQ(curved.element_nodes(e), built.element_nodes(e)) << "element " << e;
    }
    EXPECT_EQ(curved.edge_pool(), built.edge_pool());
    EXPECT_EQ(curved.face_pool(), built.face_pool());
    EXPECT_EQ(curved.interior_pool(), built.interior_pool());
  }
}

// Elements off the CAD stay straight-sided: every node, the interior ones too, at the linear map's
// image of its reference node (a tetrahedron, a prism and a hexahedron sharing faces, skewed;
// orders 2-4). Pins each interior node to its slot, which a comparison with a mesh built from the
// curved mesh's own node lists cannot see.
TEST(CurveMesh, ElementsOffTheCadKeepEveryNodeOnTheirLinearMap) {
  mesh::Mesh linear(1, NodeSet::GLL);
  const auto skew = [](double x, double y, double z) { return Eigen::Vector3d(x + 0.2 * y, y + 0.1 * z, z + 0.3 * x); };
  // Hexahedron 0-7 (Gmsh order; vertex 6 moved: not a parallelepiped), a prism 1 8 2 / 5 9 6 on
  // its +x side, a tetrahedron on the prism.
  const std::vector<Eigen::Vector3d> points = {skew(0, 0, 0), skew(1, 0, 0), skew(1, 1, 0), skew(0, 1, 0),
                                               skew(0, 0, 1), skew(1, 0, 1), skew(1.1, 1.2, 1.05), skew(0, 1, 1),
                                               skew(2, 0.5, 0), skew(2, 0.5, 1), skew(1.5, 0.5, 2)};
  for (const Eigen::Vector3d& x : points) linear.add_node(x);
  linear.add_element(Shape::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  linear.add_element(Shape::Prism, {1, 8, 2, 5, 9, 6});
  linear.add_element(Shape::Tetrahedron, {5, 9, 6, 10});
  for (int P = 2; P <= 4; ++P) {
    SCOPED_TRACE("P = " + std::to_string(P));
    const mesh::Mesh curved = curve_mesh(linear, *wing().model, {P, NodeSet::GLL, 50, 1e-10});
    for (std::size_t e = 0; e < curved.elements().size(); ++e) {
      const Shape shape = curved.elements()[e].shape;
      const std::vector<mesh::NodeId> ids = curved.element_nodes(e);
      Eigen::MatrixX3d corners(num_vertices(shape), 3);
      for (int v = 0; v < num_vertices(shape); ++v) corners.row(v) = curved.node(ids[static_cast<std::size_t>(v)]).transpose();
      const Eigen::MatrixX3d expected =
          LagrangeBasis(shape, 1, NodeSet::Equispaced).values(reference_nodes(shape, P, NodeSet::GLL)) * corners;
      ASSERT_EQ(static_cast<Eigen::Index>(ids.size()), expected.rows());
      for (std::size_t i = 0; i < ids.size(); ++i)
        EXPECT_LT((curved.node(ids[i]) - expected.row(static_cast<Eigen::Index>(i)).transpose()).norm(), 1e-12)
            << to_string(shape) << " node " << i;
    }
  }
}

// add_element_as refuses a node list that is not the adopted entities' (what add_element would
// have refused, or silently taken as the first element's word).
TEST(CurveMesh, AddElementAsRefusesAnotherEntitysNodes) {
  const mesh::Mesh linear = upper_layer(4, 2, 0.02, false);
  const mesh::Mesh curved = curve_mesh(linear, *wing().model, {3, NodeSet::GLL, 50, 1e-10});
  std::vector<mesh::NodeId> edge_nodes, face_nodes;
  for (std::size_t e = 0; e < curved.edges().size(); ++e)
    for (std::size_t k = 1; k + 1 < curved.edge_nodes(e).size(); ++k) edge_nodes.push_back(curved.edge_nodes(e)[k]);
  const std::size_t stride = 4;  // a quadrilateral's interior nodes at order 3
  for (std::size_t f = 0; f < curved.faces().size(); ++f) {
    const mesh::Face& face = curved.faces()[f];
    const std::size_t count = face.num_vertices == 3 ? 1 : 4;
    for (std::size_t k = 0; k < stride; ++k)
      face_nodes.push_back(k < count ? curved.face_pool()[face.first_node + k] : mesh::kNoNode);
  }
  mesh::Mesh again(3, NodeSet::GLL);
  for (mesh::NodeId v = 0; v < curved.num_nodes(); ++v) again.add_node(curved.node(v));
  again.adopt_entities(linear, edge_nodes, face_nodes, stride);
  // The linear mesh's elements are in regions 1 and 2 ("wing_layer", "junction"): this one has only
  // "fluid" until it copies them.
  EXPECT_THROW(again.add_element_as(linear, 0, curved.element_nodes(0)), std::invalid_argument);
  again.copy_regions_from(curved);
  EXPECT_THROW(again.adopt_entities(linear, edge_nodes, face_nodes, stride), std::logic_error);
  std::vector<mesh::NodeId> ids = curved.element_nodes(0);
  EXPECT_THROW(again.add_element_as(linear, 1, curved.element_nodes(1)), std::logic_error);  // not the next
  std::swap(ids[6], ids[7]);  // two edge nodes of the first edge
  EXPECT_THROW(again.add_element_as(linear, 0, ids), std::logic_error);
  std::swap(ids[6], ids[7]);
  EXPECT_EQ(again.add_element_as(linear, 0, ids), 0u);
  EXPECT_EQ(again.element_nodes(0), curved.element_nodes(0));
  mesh::Mesh wrong(3, NodeSet::GLL);
  EXPECT_THROW(wrong.adopt_entities(linear, edge_nodes, face_nodes, 3), std::invalid_argument);

  // Given only the interior nodes (the curving's fast path), the next element in order is made
  // as add_element_as makes it; a wrong count, an unknown id or the wrong element is refused.
  const std::vector<int> inner = [&] {
    std::vector<int> positions;
    const mesh::NodeLayout& layout = mesh::node_layout(curved.elements()[1].shape, 3);
    for (std::size_t i = 0; i < layout.slots.size(); ++i)
      if (layout.slots[i].kind == mesh::NodeSlot::Interior) positions.push_back(static_cast<int>(i));
    return positions;
  }();
  ASSERT_FALSE(inner.empty());  // a prism or hexahedron has interior nodes at order 3
  std::vector<mesh::NodeId> interior;
  for (int i : inner) interior.push_back(curved.element_nodes(1)[static_cast<std::size_t>(i)]);
  EXPECT_THROW(again.add_element_adopted(linear, 2, interior), std::logic_error);  // not the next
  EXPECT_THROW(again.add_element_adopted(linear, 1, {}), std::invalid_argument);
  std::vector<mesh::NodeId> unknown = interior;
  unknown.back() = static_cast<mesh::NodeId>(curved.num_nodes());
  EXPECT_THROW(again.add_element_adopted(linear, 1, unknown), std::invalid_argument);
  EXPECT_EQ(again.add_element_adopted(linear, 1, interior), 1u);
  EXPECT_EQ(again.element_nodes(1), curved.element_nodes(1));
}

TEST(CurveMesh, SkinStaysStraightAndAllElementsAreValid) {
  const int P = 3;
  const mesh::Mesh linear = upper_layer(12, 2, 0.02, true);
  const mesh::Mesh curved = curve_mesh(linear, *wing().model, {P, NodeSet::GLL, 50, 1e-10});
  const LagrangeBasis tri(Shape::Triangle, P, NodeSet::GLL);
  for (std::size_t e = 0; e < curved.elements().size(); ++e) {
    const Eigen::MatrixX3d X = curved.element_coordinates(e);
    const JacobianBounds bounds = certify_jacobian(Shape::Prism, P, NodeSet::GLL, X);
    EXPECT_TRUE(bounds.valid) << "element " << e << " min det J >= " << bounds.min_lower;
    // The skin face (3, 4, 5) is flat: its nodes are the affine map of its vertices.
    const mesh::Element& el = curved.elements()[e];
    const long f = curved.find_face({el.vertices[3], el.vertices[4], el.vertices[5]});
    ASSERT_GE(f, 0);
    const std::vector<mesh::NodeId> ids = curved.face_nodes(f);
    const Eigen::Vector3d a = curved.node(ids[0]), b = curved.node(ids[1]), c = curved.node(ids[2]);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const Eigen::Vector3d expected = a + tri.nodes()(i, 0) * (b - a) + tri.nodes()(i, 1) * (c - a);
      EXPECT_LT((curved.node(ids[i]) - expected).norm(), 1e-12);
    }
  }
}

// Max relative geometric error of the curved upper layer for each chordwise count.
std::vector<double> errors_under_refinement(const cad::Model& model, int P, const std::vector<int>& chordwise) {
  std::vector<double> errors;
  for (int n : chordwise) {
    CurvingStats st;
    const mesh::Mesh curved = curve_mesh(upper_layer(model, n, 2, 0.02, true), model, {P, NodeSet::GLL, 50, 1e-10}, &st);
    EXPECT_EQ(st.optimisation_fallbacks, 0) << "P = " << P << ", " << n << " chordwise";
    errors.push_back(geometric_error(curved, model, 1.0, 8).max_rel);
  }
  return errors;
}

// Chordwise refinement with cosine clustering (the leading-edge radius, 0.016 chord, must be resolved
// before the error is asymptotic); the surface is straight spanwise, so 2 spanwise segments do not
// limit the error. Expected: max error ~ h^(P+1), every observed rate >= P + 0.5 (8 chordwise cells
// are not asymptotic yet at P = 1, 3). At 64 cells P = 4 is at ~1e-11, still above the ~1e-13 floor
// of the projections that measure it. The default placement (Parameter) is tested; with Springs the
// rate at P = 3, 4 drops to ~3 next to the leading edge (see curve_mesh.hpp).
void expect_convergence(const cad::Model& model, const char* backend, const std::vector<int>& levels) {
  for (int P = 1; P <= 4; ++P) {
    const std::vector<double> e = errors_under_refinement(model, P, levels);
    std::printf("%s P = %d: max relative geometric error", backend, P);
    for (double x : e) std::printf(" %.3e", x);
    std::printf("; rates");
    for (std::size_t k = 1; k < e.size(); ++k) std::printf(" %.2f", std::log2(e[k - 1] / e[k]));
    std::printf("\n");
    for (std::size_t k = 1; k < e.size(); ++k)
      EXPECT_GE(std::log2(e[k - 1] / e[k]), P + 0.5) << backend << " P = " << P << " level " << k;
  }
}

TEST(CurveMesh, GeometricErrorConvergesUnderRefinement) {
  expect_convergence(*wing().model, "analytic", {16, 32, 64});
}

#ifdef SEMIMESH_HAVE_OCC
TEST(CurveMesh, GeometricErrorConvergesUnderRefinementOnOccBSplines) {
  cad::Source source;
  source.params.set("naca.farfield", "false");
  const std::unique_ptr<cad::Model> model = occ::load_occ(source);
  expect_convergence(*model, "occ", {16, 32});  // OCC projections are slower: one rate per order
}
#endif

TEST(CurveMesh, GeometricErrorFallsWithOrder) {
  const mesh::Mesh linear = upper_layer(8, 2, 0.02, true);
  double previous = geometric_error(curve_mesh(linear, *wing().model, {1, NodeSet::GLL, 50, 1e-10}), *wing().model, 1.0)
                        .max_rel;
  EXPECT_GT(previous, 1e-3);  // straight sides are visibly off the wing
  for (int P = 2; P <= 5; ++P) {
    const double e = geometric_error(curve_mesh(linear, *wing().model, {P, NodeSet::GLL, 50, 1e-10}), *wing().model, 1.0)
                         .max_rel;
    EXPECT_LT(e, 0.5 * previous) << "P = " << P;
    previous = e;
  }
}

TEST(CurveMesh, CurvedThenSplitLayerIsValidAndKeepsTheWing) {
  // The pipeline's order: curve the one-layer near field, then split it into 5 layers of ratio 2.
  const int P = 3;
  const mesh::Mesh curved = curve_mesh(upper_layer(12, 2, 0.02, true), *wing().model, {P});
  std::vector<std::size_t> all(curved.elements().size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = e;
  SplitStats stats;
  const mesh::Mesh layers = split_layers(curved, all, {5, 2.0}, {}, &stats);
  EXPECT_EQ(stats.elements_out, 5 * stats.elements_in);
  EXPECT_NEAR(stats.first_cell_height_min, 0.02 / 31.0, 1e-3 * 0.02 / 31.0);  // straight vertical edges
  for (std::size_t e = 0; e < layers.elements().size(); ++e)
    EXPECT_TRUE(certify_jacobian(Shape::Prism, P, NodeSet::GLL, layers.element_coordinates(e)).valid) << e;
  // The wing faces are the curved mesh's own: same geometric error.
  EXPECT_DOUBLE_EQ(geometric_error(layers, *wing().model, 1.0, 6).max_rel,
                   geometric_error(curved, *wing().model, 1.0, 6).max_rel);
}

TEST(GeometricError, MeasuresOnlyTheSurfacesItIsGiven) {
  // The straight-sided layer's wing faces are off the curved upper surface; a list without that
  // surface measures nothing there (the pipeline leaves a sphere far field straight on purpose).
  const mesh::Mesh linear = upper_layer(6, 2, 0.02, false);
  const GeometricError all = geometric_error(linear, *wing().model, 1.0, 6);
  const GeometricError upper = geometric_error(linear, *wing().model, 1.0, 6, {wing().upper});
  const GeometricError other = geometric_error(linear, *wing().model, 1.0, 6, {wing().upper + 1});
  EXPECT_GT(all.max_rel, 1e-5);
  EXPECT_EQ(upper.max_rel, all.max_rel);
  EXPECT_EQ(upper.samples, all.samples);
  EXPECT_EQ(other.samples, 0);
}

// `first` (upper_layer) and a second prism layer on top of it: new nodes and elements after the
// first layer's, as the far field comes after the near field in the pipeline.
mesh::Mesh with_second_layer(const mesh::Mesh& first) {
  mesh::Mesh full = first;
  const auto n = static_cast<mesh::NodeId>(first.num_nodes() / 2);  // bottom nodes, then top nodes
  for (mesh::NodeId i = 0; i < n; ++i) full.add_node(2.0 * first.node(n + i) - first.node(i));
  for (const mesh::Element& e : first.elements()) {
    std::vector<mesh::NodeId> top;
    for (int v = 3; v < 6; ++v) top.push_back(e.vertices[v]);
    for (int v = 3; v < 6; ++v) top.push_back(e.vertices[v] + n);
    full.add_element(Shape::Prism, top);
  }
  return full;
}

void expect_same_curving(const mesh::Mesh& a, const mesh::Mesh& b, const CurvingStats& sa, const CurvingStats& sb) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  for (mesh::NodeId id = 0; id < a.num_nodes(); ++id) {
    ASSERT_EQ(std::memcmp(a.node(id).data(), b.node(id).data(), 3 * sizeof(double)), 0) << "node " << id;
    const mesh::CadAttachment &x = a.cad_attachment(id), &y = b.cad_attachment(id);
    ASSERT_TRUE(x.kind == y.kind && x.entity == y.entity && x.u == y.u && x.v == y.v) << "node " << id;
  }
  ASSERT_EQ(a.elements().size(), b.elements().size());
  for (std::size_t e = 0; e < a.elements().size(); ++e) {
    ASSERT_EQ(a.element_nodes(e), b.element_nodes(e)) << "element " << e;
    ASSERT_EQ(a.elements()[e].region, b.elements()[e].region) << "element " << e;
  }
  ASSERT_EQ(a.boundary_faces().size(), b.boundary_faces().size());
  for (std::size_t f = 0; f < a.boundary_faces().size(); ++f) {
    ASSERT_EQ(a.boundary_face_nodes(f), b.boundary_face_nodes(f)) << "boundary face " << f;
    ASSERT_EQ(a.boundary_faces()[f].group, b.boundary_faces()[f].group) << "boundary face " << f;
  }
  EXPECT_EQ(sa.edges_on_curves, sb.edges_on_curves);
  EXPECT_EQ(sa.edges_on_surfaces, sb.edges_on_surfaces);
  EXPECT_EQ(sa.faces_on_surfaces, sb.faces_on_surfaces);
  EXPECT_EQ(sa.optimisation_fallbacks, sb.optimisation_fallbacks);
  EXPECT_EQ(sa.max_projection_distance, sb.max_projection_distance);
}

// The fast path (nodes taken from the mesh curved ahead) against the reference (every node placed
// here): the same bits, statistics and numbering, whether all, some or none of it can be taken.
TEST(CurveMesh, TakesWhatWasCurvedAheadAndGivesTheSameMesh) {
  const mesh::Mesh first = upper_layer(6, 2, 0.02, true);
  const mesh::Mesh full = with_second_layer(first);
  const std::size_t first_entities = first.edges().size() + first.faces().size() + first.elements().size();
  const std::atomic<bool> go{false};
  for (int P = 2; P <= 4; ++P)
    for (NodePlacement placement : {NodePlacement::Parameter, NodePlacement::Springs}) {
      SCOPED_TRACE("P = " + std::to_string(P) + (placement == NodePlacement::Springs ? ", springs" : ""));
      const CurvingParams params{P, NodeSet::GLL, 50, 1e-10, placement};
      CurvingStats reference_stats;
      const mesh::Mesh reference = curve_mesh(full, *wing().model, params, &reference_stats);

      const CurvedAhead ahead = curve_ahead(first, *wing().model, params, go);
      ASSERT_FALSE(ahead.empty());
      CurvingStats stats;
      std::size_t taken = 0;
      expect_same_curving(curve_mesh(full, *wing().model, params, &stats, {}, &ahead, &taken), reference, stats,
                          reference_stats);
      EXPECT_EQ(taken, first_entities);  // all of the first layer

      // The first layer's side faces on a boundary of the whole mesh (not of the first layer's):
      // those faces, and the elements they bound, are placed again.
      mesh::Mesh sides = full;
      std::size_t side_faces = 0;
      for (std::size_t f = 0; f < first.faces().size() && side_faces < 3; ++f)
        if (first.faces()[f].num_vertices == 4) {
          sides.add_boundary_face("side", Shape::Quadrilateral, first.face_nodes(f));
          ++side_faces;
        }
      CurvingStats sides_reference_stats;
      const mesh::Mesh sides_reference = curve_mesh(sides, *wing().model, params, &sides_reference_stats);
      expect_same_curving(curve_mesh(sides, *wing().model, params, &stats, {}, &ahead, &taken), sides_reference,
                          stats, sides_reference_stats);
      EXPECT_GT(taken, 0u);
      EXPECT_LT(taken, first_entities);

      // A node of the first layer moved since: nothing is taken.
      mesh::Mesh moved = full;
      moved.place_node(first.elements()[0].vertices[3], first.node(first.elements()[0].vertices[3]) * 1.0001);
      CurvingStats moved_reference_stats;
      const mesh::Mesh moved_reference = curve_mesh(moved, *wing().model, params, &moved_reference_stats);
      expect_same_curving(curve_mesh(moved, *wing().model, params, &stats, {}, &ahead, &taken), moved_reference,
                          stats, moved_reference_stats);
      EXPECT_EQ(taken, 0u);
    }
}

TEST(CurveMesh, CurvingAheadStopsWhenToldAndTakesNothingOfAnotherOrder) {
  const mesh::Mesh first = upper_layer(6, 2, 0.02, true);
  const std::atomic<bool> stop{true}, go{false};
  EXPECT_TRUE(curve_ahead(first, *wing().model, {3}, stop).empty());
  const CurvedAhead ahead = curve_ahead(first, *wing().model, {3}, go);
  ASSERT_FALSE(ahead.empty());
  EXPECT_EQ(ahead.linear_nodes, first.num_nodes());
  std::size_t taken = 1;
  CurvingStats stats, reference_stats;
  const mesh::Mesh full = with_second_layer(first);
  expect_same_curving(curve_mesh(full, *wing().model, {4}, &stats, {}, &ahead, &taken),
                      curve_mesh(full, *wing().model, {4}, &reference_stats), stats, reference_stats);
  EXPECT_EQ(taken, 0u);
}

// certify_ahead's bounds given to certify_mesh: the reference's validity, most of it taken; stopped
// before the first element, none.
TEST(CertifyAhead, GivesCertifyMeshsValidityAndStopsWhenTold) {
  const mesh::Mesh curved = curve_mesh(upper_layer(12, 2, 0.02, true), *wing().model, {4});
  const std::atomic<bool> stop{true}, go{false};
  EXPECT_TRUE(certify_ahead(curved, 8, 0.1, stop).empty());
  const std::vector<InheritedBounds> ahead = certify_ahead(curved, 8, 0.1, go);
  ASSERT_EQ(ahead.size(), curved.elements().size());
  const MeshValidity reference = certify_mesh(curved, 8, 0.1);
  const MeshValidity taken = certify_mesh(curved, 8, 0.1, {}, &ahead);
  EXPECT_GT(taken.certified_before, ahead.size() / 2);
  EXPECT_EQ(taken.inherited, 0u);  // the elements' own certificates: none from a parent
  EXPECT_EQ(reference.certified_before, 0u);
  EXPECT_EQ(taken.invalid_elements, reference.invalid_elements);
  EXPECT_EQ(taken.min_scaled_jacobian, reference.min_scaled_jacobian);
  EXPECT_EQ(taken.median_scaled_jacobian, reference.median_scaled_jacobian);
  for (std::size_t e = 0; e < ahead.size(); ++e) {
    EXPECT_EQ(ahead[e].element, e);
    EXPECT_EQ(ahead[e].fingerprint, element_fingerprint(curved, e));
    EXPECT_EQ(ahead[e].bounds.min_lower, reference.bounds[e].min_lower) << e;
    EXPECT_EQ(ahead[e].bounds.max_upper, reference.bounds[e].max_upper) << e;
  }
}

// certify_behind on every other element, the mesh's elements made available one at a time by
// another thread: the reference's certificates of exactly those; with depth 0, the certificates
// certify_mesh takes give its validity; nothing made available and told to stop, none.
TEST(CertifyBehind, CertifiesTheWantedElementsAsTheyAreBuiltAndStopsWhenTold) {
  const mesh::Mesh curved = curve_mesh(upper_layer(12, 2, 0.02, true), *wing().model, {4});
  const std::size_t n = curved.elements().size();
  std::vector<std::size_t> wanted;
  for (std::size_t e = 1; e < n; e += 2) wanted.push_back(e);
  const std::atomic<bool> stop{true}, go{false};
  const std::atomic<std::size_t> none{0};
  EXPECT_TRUE(certify_behind(curved, wanted, none, 8, 0.1, stop).empty());
  std::atomic<std::size_t> built{0};
  std::thread builder([&] {
    for (std::size_t e = 1; e <= n; ++e) {
      std::this_thread::sleep_for(std::chrono::microseconds(50));
      built.store(e, std::memory_order_release);
    }
  });
  const std::vector<InheritedBounds> behind = certify_behind(curved, wanted, built, 8, 0.1, go);
  builder.join();
  const MeshValidity reference = certify_mesh(curved, 8, 0.1);
  ASSERT_EQ(behind.size(), wanted.size());
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    EXPECT_EQ(behind[k].element, wanted[k]);
    EXPECT_EQ(behind[k].fingerprint, element_fingerprint(curved, wanted[k]));
    EXPECT_EQ(behind[k].bounds.min_lower, reference.bounds[wanted[k]].min_lower) << wanted[k];
    EXPECT_EQ(behind[k].bounds.max_upper, reference.bounds[wanted[k]].max_upper) << wanted[k];
  }
  const std::vector<InheritedBounds> first_only = certify_behind(curved, wanted, built, 0, 0.1, go);
  const MeshValidity taken = certify_mesh(curved, 8, 0.1, {}, &first_only);
  EXPECT_GT(taken.certified_before, wanted.size() / 2);
  EXPECT_EQ(taken.inherited, 0u);
  EXPECT_EQ(taken.invalid_elements, reference.invalid_elements);
  EXPECT_EQ(taken.min_scaled_jacobian, reference.min_scaled_jacobian);
  EXPECT_EQ(taken.median_scaled_jacobian, reference.median_scaled_jacobian);
  for (std::size_t e = 0; e < n; ++e) {
    EXPECT_EQ(taken.bounds[e].min_lower, reference.bounds[e].min_lower) << e;
    EXPECT_EQ(taken.bounds[e].max_upper, reference.bounds[e].max_upper) << e;
  }
}

TEST(CurveMesh, RejectsBadInput) {
  const mesh::Mesh linear = upper_layer(4, 1, 0.02, false);
  EXPECT_THROW(curve_mesh(linear, *wing().model, {0, NodeSet::GLL, 50, 1e-10}), std::invalid_argument);
  EXPECT_THROW(curve_mesh(curve_mesh(linear, *wing().model, {2}), *wing().model, {3}), std::invalid_argument);
  EXPECT_THROW(geometric_error(linear, *wing().model, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
