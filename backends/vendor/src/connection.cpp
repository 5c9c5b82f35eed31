#include "connection.hpp"

#include "semimesh/vendor/vendor_error.hpp"

namespace semimesh::vendor {

std::string describe(const EntityRef& entity) {
  std::string out = entity.type;
  if (entity.vendor_id != VC_NULL_ENTITY) out += " #" + std::to_string(entity.vendor_id);
  if (entity.name && !entity.name->empty()) out += " '" + *entity.name + "'";
  if (entity.semimesh_id >= 0) out += " (semimesh id " + std::to_string(entity.semimesh_id) + ")";
  return out;
}

Connection::Connection(const std::string& path, const std::string& options) {
  const std::string file = "file '" + path + "'";
  if (vc_api_version() != VC_API_VERSION)
    throw cad::CadError(cad::CadError::Kind::BackendUnavailable,
                        "vendor CAD: the linked vendor library implements API version " +
                            std::to_string(vc_api_version()) + " but semimesh was built for version " +
                            std::to_string(VC_API_VERSION) + "; rebuild against the matching SDK");
  vc_status status = vc_session_open(&session_);
  if (status != VC_OK) throw vendor_error(status, "vc_session_open", file, vc_error_message(nullptr));
  status = vc_model_load(session_, path.c_str(), options.c_str(), &model_);
  if (status != VC_OK) {
    cad::CadError error = vendor_error(status, "vc_model_load", file, vc_error_message(session_));
    vc_session_close(session_);
    throw error;
  }
}

Connection::~Connection() {
  // The model first: it belongs to the session. Failures cannot be reported from a destructor.
  vc_model_free(model_);
  vc_session_close(session_);
}

void Connection::fail(vc_status status, const char* function, const EntityRef& entity) const {
  throw vendor_error(status, function, describe(entity), vc_error_message(session_));
}

}  // namespace semimesh::vendor
