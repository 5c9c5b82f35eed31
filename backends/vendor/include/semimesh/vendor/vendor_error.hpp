// How a vendor status code becomes a cad::CadError (used by the adapter, tested on its own).
#pragma once

#include "semimesh/cad/error.hpp"

#include <string>

namespace semimesh::vendor {

/// The CadError kind a vendor status (VC_ERR_*) stands for: file errors stay file errors, option
/// and argument errors are BadParameter, an empty model is NoGeometry, the rest is Geometry.
cad::CadError::Kind error_kind(int status);

/// "vendor CAD: <function> failed on <entity>: <VC_ERR_NAME>: <vendor message>".
/// `entity` says what was queried ("edge #7 'te_upper' (semimesh curve 3)" or "file 'x.vcad'").
cad::CadError vendor_error(int status, const std::string& function, const std::string& entity,
                           const std::string& vendor_message);

}  // namespace semimesh::vendor
