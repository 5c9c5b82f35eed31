// Threads: curving, splitting and certification of the NACA O-shell give byte-identical results with
// 1 and 2 threads, and with or without a progress callback (which is called from the calling thread
// only, a bounded number of times, with fractions that never decrease and end at 1); certify_mesh
// agrees with a serial loop of certify_jacobian.
#include "o_shell_fixture.hpp"

#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace semimesh::ho {
namespace {

struct ThreadedRun {
  mesh::Mesh curved, split;
  MeshValidity validity;
};

ThreadedRun run_with_threads(int threads) {
  omp_set_num_threads(threads);
  ThreadedRun r{curve_mesh(testing::coarse_o_shell().field.mesh, *testing::coarse_o_shell().model, {3, NodeSet::GLL, 50, 1e-10}), mesh::Mesh(1), {}};
  r.split = split_layers(r.curved, testing::all_elements(r.curved), {5, 2.0});
  r.validity = certify_mesh(r.split);
  omp_set_num_threads(omp_get_num_procs());
  return r;
}

void expect_identical(const mesh::Mesh& a, const mesh::Mesh& b, const char* what) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes()) << what;
  for (mesh::NodeId id = 0; id < a.num_nodes(); ++id) {
    ASSERT_EQ(std::memcmp(a.node(id).data(), b.node(id).data(), 3 * sizeof(double)), 0) << what << " node " << id;
    const mesh::CadAttachment &ca = a.cad_attachment(id), &cb = b.cad_attachment(id);
    ASSERT_EQ(ca.kind, cb.kind) << what << " node " << id;
    ASSERT_EQ(ca.entity, cb.entity) << what << " node " << id;
    ASSERT_EQ(std::memcmp(&ca.u, &cb.u, sizeof(double)), 0) << what << " node " << id;
    ASSERT_EQ(std::memcmp(&ca.v, &cb.v, sizeof(double)), 0) << what << " node " << id;
  }
  ASSERT_EQ(a.elements().size(), b.elements().size()) << what;
  for (std::size_t e = 0; e < a.elements().size(); ++e) {
    ASSERT_EQ(a.elements()[e].shape, b.elements()[e].shape) << what << " element " << e;
    ASSERT_EQ(a.element_nodes(e), b.element_nodes(e)) << what << " element " << e;
  }
  ASSERT_EQ(a.boundary_faces().size(), b.boundary_faces().size()) << what;
  for (std::size_t f = 0; f < a.boundary_faces().size(); ++f)
    ASSERT_EQ(a.boundary_face_nodes(f), b.boundary_face_nodes(f)) << what << " boundary face " << f;
}

TEST(HoMeshThreads, OneAndTwoThreadsGiveByteIdenticalMeshes) {
  ASSERT_GE(omp_get_max_threads(), 1);
  const ThreadedRun one = run_with_threads(1), two = run_with_threads(2);
  ASSERT_GT(one.curved.elements().size(), 100u);
  expect_identical(one.curved, two.curved, "curved");
  expect_identical(one.split, two.split, "split");
  ASSERT_EQ(one.validity.bounds.size(), two.validity.bounds.size());
  for (std::size_t e = 0; e < one.validity.bounds.size(); ++e) {
    EXPECT_EQ(std::memcmp(&one.validity.bounds[e].min_lower, &two.validity.bounds[e].min_lower, sizeof(double)), 0);
    EXPECT_EQ(one.validity.bounds[e].valid, two.validity.bounds[e].valid);
  }
  EXPECT_EQ(one.validity.min_scaled_jacobian, two.validity.min_scaled_jacobian);
  EXPECT_EQ(one.validity.median_scaled_jacobian, two.validity.median_scaled_jacobian);
}

// Records what a progress callback receives and from which thread.
struct ProgressLog {
  std::vector<double> fractions;
  std::vector<std::string> steps;
  bool other_thread = false;
  ProgressCallback callback() {
    const std::thread::id caller = std::this_thread::get_id();
    return [this, caller](double fraction, const std::string& step) {
      other_thread = other_thread || std::this_thread::get_id() != caller;
      fractions.push_back(fraction);
      steps.push_back(step);
    };
  }
  void expect_sound(const char* what, std::size_t loops) const {
    ASSERT_FALSE(fractions.empty()) << what;
    EXPECT_FALSE(other_thread) << what << ": called from a thread other than the caller's";
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end())) << what;
    EXPECT_GE(fractions.front(), 0.0) << what;
    EXPECT_EQ(fractions.back(), 1.0) << what;
    EXPECT_LE(fractions.size(), loops * (ProgressCounter::kMarks + 2)) << what << ": not throttled";
  }
};

TEST(HoMeshThreads, ProgressIsReportedFromTheCallerAndDoesNotChangeTheResult) {
  omp_set_num_threads(2);
  ProgressLog curving, splitting, certifying;
  const mesh::Mesh curved =
      curve_mesh(testing::coarse_o_shell().field.mesh, *testing::coarse_o_shell().model, {3, NodeSet::GLL, 50, 1e-10}, nullptr, curving.callback());
  std::vector<LayerSplit> all;
  for (std::size_t e : testing::all_elements(curved)) all.push_back({e, {2, -1}, {0, 0}});
  const mesh::Mesh split = split_layers(curved, all, {{{5, 2.0}, {}}}, nullptr, nullptr, splitting.callback());
  const MeshValidity validity = certify_mesh(split, 8, 0.0, certifying.callback());
  omp_set_num_threads(omp_get_num_procs());
  curving.expect_sound("curve_mesh", 3);
  splitting.expect_sound("split_layers", 1);
  certifying.expect_sound("certify_mesh", 1);
  EXPECT_NE(std::find(curving.steps.begin(), curving.steps.end(), "faces"), curving.steps.end());
  EXPECT_GT(certifying.fractions.size(), 10u) << "certification reports along the way, not only at the end";

  const ThreadedRun quiet = run_with_threads(2);
  expect_identical(quiet.curved, curved, "curved with progress");
  expect_identical(quiet.split, split, "split with progress");
  EXPECT_EQ(quiet.validity.min_scaled_jacobian, validity.min_scaled_jacobian);
}

TEST(CertifyMesh, AgreesWithASerialLoopAndLocatesInvalidElements) {
  mesh::Mesh curved = curve_mesh(testing::coarse_o_shell().field.mesh, *testing::coarse_o_shell().model, {2, NodeSet::GLL, 50, 1e-10});
  // Make two elements invalid for certain: the midnode m of the layer edge from body vertex 0 to
  // skin vertex 3 (not on the CAD) goes to 2 x0 - x3, which reverses dx/dzeta at vertex 0
  // ((-3 x0 + 4 m - x3) / 2 = -5/2 (x3 - x0)) while the body-face derivatives there stay: det J < 0
  // at a vertex, a value the certification must see.
  const auto& prism_edges = ho::edges(Shape::Prism);
  const std::size_t layer_edge =
      static_cast<std::size_t>(std::find(prism_edges.begin(), prism_edges.end(), std::array<int, 2>{0, 3}) - prism_edges.begin());
  ASSERT_LT(layer_edge, prism_edges.size());
  const std::size_t bad[2] = {3, curved.elements().size() / 2};
  for (std::size_t e : bad) {
    const std::vector<mesh::NodeId> ids = curved.element_nodes(e);
    const mesh::NodeId mid = ids[6 + layer_edge];  // order 2: one node per edge, in edge order
    ASSERT_EQ(curved.cad_attachment(mid).kind, mesh::CadAttachment::None) << e;
    curved.place_node(mid, 2.0 * curved.node(ids[0]) - curved.node(ids[3]));
  }
  const MeshValidity v = certify_mesh(curved);
  ASSERT_EQ(v.bounds.size(), curved.elements().size());
  std::vector<double> scaled;
  std::vector<std::size_t> invalid;
  for (std::size_t e = 0; e < curved.elements().size(); ++e) {
    const JacobianBounds b = certify_jacobian(Shape::Prism, 2, NodeSet::GLL, curved.element_coordinates(e));
    EXPECT_EQ(b.min_lower, v.bounds[e].min_lower) << e;
    EXPECT_EQ(b.max_upper, v.bounds[e].max_upper) << e;
    EXPECT_EQ(b.valid, v.bounds[e].valid) << e;
    if (!b.valid) invalid.push_back(e);
    scaled.push_back(scaled_jacobian(b));
  }
  EXPECT_GE(invalid.size(), 2u);  // the pushed node may also belong to a neighbour
  EXPECT_NE(std::find(invalid.begin(), invalid.end(), bad[0]), invalid.end());
  EXPECT_NE(std::find(invalid.begin(), invalid.end(), bad[1]), invalid.end());
  EXPECT_EQ(v.invalid_elements, invalid);
  EXPECT_EQ(v.invalid, invalid.size());
  ASSERT_EQ(v.invalid_centroids.size(), invalid.size());
  const mesh::Element& el = curved.elements()[invalid[0]];
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int k = 0; k < 6; ++k) centroid += curved.node(el.vertices[k]) / 6.0;
  EXPECT_LT((v.invalid_centroids[0] - centroid).norm(), 1e-12);
  std::sort(scaled.begin(), scaled.end());
  EXPECT_EQ(v.min_scaled_jacobian, scaled.front());
  EXPECT_EQ(v.median_scaled_jacobian, scaled[(scaled.size() - 1) / 2]);
  EXPECT_LT(v.min_scaled_jacobian, 0.0);
}

TEST(CertifyMesh, RejectsBadInput) {
  EXPECT_THROW(certify_mesh(testing::coarse_o_shell().field.mesh, -1), std::invalid_argument);
  const MeshValidity empty = certify_mesh(mesh::Mesh(2));
  EXPECT_TRUE(empty.all_valid());
  EXPECT_EQ(empty.min_scaled_jacobian, 1.0);
}

}  // namespace
}  // namespace semimesh::ho
