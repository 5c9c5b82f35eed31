// Every vendor status code becomes a CadError of the right kind whose message names the vendor
// function, the entity, the status and the vendor's own words.
#include "semimesh/vendor/vendor_error.hpp"

#include "vendor_cad_api.h"

#include <gtest/gtest.h>

namespace semimesh::vendor {
namespace {

using Kind = cad::CadError::Kind;

struct Expected {
  int status;
  const char* name;
  Kind kind;
};

// The mapping as documented in vendor_error.hpp, written out by hand.
const Expected kTable[] = {
    {VC_ERR_FILE_NOT_FOUND, "VC_ERR_FILE_NOT_FOUND", Kind::FileNotFound},
    {VC_ERR_BAD_FILE, "VC_ERR_BAD_FILE", Kind::FileUnreadable},
    {VC_ERR_BAD_HANDLE, "VC_ERR_BAD_HANDLE", Kind::Geometry},
    {VC_ERR_BAD_PARAM, "VC_ERR_BAD_PARAM", Kind::BadParameter},
    {VC_ERR_OUT_OF_RANGE, "VC_ERR_OUT_OF_RANGE", Kind::Geometry},
    {VC_ERR_UNKNOWN_OPTION, "VC_ERR_UNKNOWN_OPTION", Kind::BadParameter},
    {VC_ERR_WRONG_TYPE, "VC_ERR_WRONG_TYPE", Kind::Geometry},
    {VC_ERR_EMPTY_MODEL, "VC_ERR_EMPTY_MODEL", Kind::NoGeometry},
    {VC_ERR_NOT_CONVERGED, "VC_ERR_NOT_CONVERGED", Kind::Geometry},
    {VC_ERR_INTERNAL, "VC_ERR_INTERNAL", Kind::Geometry},
};

TEST(VendorError, EveryStatusMapsToItsKindAndNamesFunctionEntityAndVendorMessage) {
  for (const Expected& e : kTable) {
    SCOPED_TRACE(e.name);
    EXPECT_EQ(error_kind(e.status), e.kind);
    cad::CadError error = vendor_error(e.status, "vc_face_eval", "face #12 'wing_upper'", "the vendor's words");
    EXPECT_EQ(error.kind(), e.kind);
    const std::string message = error.what();
    EXPECT_NE(message.find("vc_face_eval"), std::string::npos) << message;
    EXPECT_NE(message.find("face #12 'wing_upper'"), std::string::npos) << message;
    EXPECT_NE(message.find(e.name), std::string::npos) << message;
    EXPECT_NE(message.find("the vendor's words"), std::string::npos) << message;
  }
}

TEST(VendorError, UnknownStatusIsAGeometryErrorWithItsNumber) {
  cad::CadError error = vendor_error(4242, "vc_edge_eval", "edge #3", "");
  EXPECT_EQ(error.kind(), Kind::Geometry);
  EXPECT_NE(std::string(error.what()).find("4242"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace semimesh::vendor
