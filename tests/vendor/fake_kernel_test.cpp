// The fake kernel behaves like a foreign C API: its own 1-based ids, status codes for every
// misuse, messages in the session. (The adapter tests rely on this behaviour.)
#include "vendor_cad_api.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

class FakeKernel : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(vc_session_open(&session_), VC_OK);
    ASSERT_EQ(vc_model_load(session_, "naca:naca.code=0012", nullptr, &model_), VC_OK) << vc_error_message(session_);
  }
  void TearDown() override { EXPECT_EQ(vc_session_close(session_), VC_OK); }

  vc_entity first(vc_entity_type type) const {
    vc_entity e = VC_NULL_ENTITY;
    EXPECT_EQ(vc_model_entity(model_, type, 1, &e), VC_OK);
    return e;
  }
  std::string message() const { return vc_error_message(session_); }

  vc_session session_ = nullptr;
  vc_model model_ = nullptr;
};

TEST_F(FakeKernel, IdsAreOneBasedSharedAcrossTypesAndNotIndices) {
  int faces = 0, edges = 0, vertices = 0;
  ASSERT_EQ(vc_model_entity_count(model_, VC_TYPE_FACE, &faces), VC_OK);
  ASSERT_EQ(vc_model_entity_count(model_, VC_TYPE_EDGE, &edges), VC_OK);
  ASSERT_EQ(vc_model_entity_count(model_, VC_TYPE_VERTEX, &vertices), VC_OK);
  ASSERT_GT(faces, 0);
  ASSERT_GT(vertices, 0);
  vc_entity vertex = first(VC_TYPE_VERTEX);
  EXPECT_GT(vertex, 1);  // bodies, faces and edges are numbered first
  vc_entity_type type = VC_TYPE_BODY;
  ASSERT_EQ(vc_entity_get_type(model_, vertex, &type), VC_OK);
  EXPECT_EQ(type, VC_TYPE_VERTEX);
  vc_entity last = VC_NULL_ENTITY;
  ASSERT_EQ(vc_model_entity(model_, VC_TYPE_VERTEX, vertices, &last), VC_OK);
  EXPECT_EQ(last, 1 + faces + edges + vertices);  // one body, then everything once
}

TEST_F(FakeKernel, IndexPastTheCountIsOutOfRange) {
  int faces = 0;
  ASSERT_EQ(vc_model_entity_count(model_, VC_TYPE_FACE, &faces), VC_OK);
  vc_entity e = VC_NULL_ENTITY;
  EXPECT_EQ(vc_model_entity(model_, VC_TYPE_FACE, faces + 1, &e), VC_ERR_OUT_OF_RANGE);
  EXPECT_EQ(vc_model_entity(model_, VC_TYPE_FACE, 0, &e), VC_ERR_OUT_OF_RANGE);  // 1-based
  EXPECT_NE(message().find("outside 1.." + std::to_string(faces)), std::string::npos) << message();
  EXPECT_EQ(e, VC_NULL_ENTITY);  // out-parameters untouched on failure
}

TEST_F(FakeKernel, UnknownIdIsBadHandleAndOtherTypeIsWrongType) {
  double t0 = 0, t1 = 0;
  EXPECT_EQ(vc_edge_range(model_, 999999, &t0, &t1), VC_ERR_BAD_HANDLE);
  EXPECT_NE(message().find("999999"), std::string::npos) << message();
  EXPECT_EQ(vc_edge_range(model_, first(VC_TYPE_FACE), &t0, &t1), VC_ERR_WRONG_TYPE);
  EXPECT_NE(message().find("is a face, not a edge"), std::string::npos) << message();
}

TEST_F(FakeKernel, ParameterOutsideTheRangeIsOutOfRangeAndNullOutputIsBadParam) {
  vc_entity edge = first(VC_TYPE_EDGE);
  double t0 = 0, t1 = 0, p[3];
  ASSERT_EQ(vc_edge_range(model_, edge, &t0, &t1), VC_OK);
  EXPECT_EQ(vc_edge_eval(model_, edge, t1 + (t1 - t0), p, nullptr, nullptr), VC_ERR_OUT_OF_RANGE);
  EXPECT_EQ(vc_edge_eval(model_, edge, t1, p, nullptr, nullptr), VC_OK);
  EXPECT_EQ(vc_edge_range(model_, edge, nullptr, &t1), VC_ERR_BAD_PARAM);
  EXPECT_NE(message().find("t0 is NULL"), std::string::npos) << message();
}

TEST_F(FakeKernel, FreedOrNullModelIsBadHandle) {
  int count = 0;
  EXPECT_EQ(vc_model_entity_count(nullptr, VC_TYPE_FACE, &count), VC_ERR_BAD_HANDLE);
  ASSERT_EQ(vc_model_free(model_), VC_OK);
  EXPECT_EQ(vc_model_entity_count(model_, VC_TYPE_FACE, &count), VC_ERR_BAD_HANDLE);
  EXPECT_NE(std::string(vc_error_message(nullptr)).find("model handle"), std::string::npos);
}

TEST_F(FakeKernel, NaturalNormalIsUnitAndCrossOfDerivatives) {
  vc_entity face = first(VC_TYPE_FACE);
  double lo[2], hi[2];
  ASSERT_EQ(vc_face_range(model_, face, lo, hi), VC_OK);
  const double uv[2] = {0.3 * lo[0] + 0.7 * hi[0], 0.6 * lo[1] + 0.4 * hi[1]};
  double du[3], dv[3], n[3];
  ASSERT_EQ(vc_face_eval(model_, face, uv, nullptr, du, dv, nullptr, nullptr, nullptr), VC_OK);
  ASSERT_EQ(vc_face_normal(model_, face, uv, n), VC_OK);
  const double c[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
  double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(n[k], c[k] / len, 1e-14);
}

}  // namespace
