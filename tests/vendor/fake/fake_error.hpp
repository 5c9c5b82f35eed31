// How the fake kernel fails internally: a vendor status with its message, turned into the return
// code (and the session's message) at the C boundary.
#pragma once

#include "vendor_cad_api.h"

#include <string>

namespace semimesh::vendor_fake {

struct FakeError {
  vc_status status;
  std::string message;
};

}  // namespace semimesh::vendor_fake
