// One vendor session with the one model loaded in it, shared by the adapter's entities.
#pragma once

#include "vendor_cad_api.h"

#include <mutex>
#include <string>

namespace semimesh::vendor {

/// What a failing call was about, for the error message. `semimesh_id` is -1 before the entity
/// has a semimesh id.
struct EntityRef {
  const char* type;          ///< "face", "edge", "vertex", "body", "model"
  vc_entity vendor_id;       ///< VC_NULL_ENTITY for the model itself
  int semimesh_id;
  const std::string* name;   ///< may be null
};

std::string describe(const EntityRef& entity);

class Connection {
 public:
  /// Opens a session and loads `path` with `options` into it; throws CadError naming the file.
  Connection(const std::string& path, const std::string& options);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  /// Runs `query(model)` under the session lock (the kernel is single-threaded per session) and
  /// turns a non-OK status into a CadError naming `function` and `entity`.
  template <class Query>
  void call(const char* function, const EntityRef& entity, Query&& query) const {
    std::lock_guard<std::mutex> lock(mutex_);
    vc_status status = query(model_);
    if (status != VC_OK) fail(status, function, entity);
  }

 private:
  [[noreturn]] void fail(vc_status status, const char* function, const EntityRef& entity) const;

  mutable std::mutex mutex_;
  vc_session session_ = nullptr;
  vc_model model_ = nullptr;
};

}  // namespace semimesh::vendor
