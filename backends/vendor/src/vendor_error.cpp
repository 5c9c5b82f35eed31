#include "semimesh/vendor/vendor_error.hpp"

#include "vendor_cad_api.h"

namespace semimesh::vendor {

cad::CadError::Kind error_kind(int status) {
  using Kind = cad::CadError::Kind;
  switch (status) {
    case VC_ERR_FILE_NOT_FOUND: return Kind::FileNotFound;
    case VC_ERR_BAD_FILE: return Kind::FileUnreadable;
    case VC_ERR_BAD_PARAM:
    case VC_ERR_UNKNOWN_OPTION: return Kind::BadParameter;
    case VC_ERR_EMPTY_MODEL: return Kind::NoGeometry;
    default: return Kind::Geometry;
  }
}

cad::CadError vendor_error(int status, const std::string& function, const std::string& entity,
                           const std::string& vendor_message) {
  std::string message = "vendor CAD: " + function + " failed on " + entity + ": " + vc_status_name(status) + " (" +
                        std::to_string(status) + ")";
  if (!vendor_message.empty()) message += ": " + vendor_message;
  return cad::CadError(error_kind(status), message);
}

}  // namespace semimesh::vendor
