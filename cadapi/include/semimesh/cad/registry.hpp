// Backends chosen by name. Every backend known to the project is listed, built or not; loading
// one that is not built fails with "backend 'X' is not available in this build (...)".
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/cad/source.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace semimesh::cad {

using BackendFactory = std::function<std::unique_ptr<Model>(const Source&)>;

struct BackendInfo {
  std::string name;
  std::string description;
  std::vector<std::string> extensions;  ///< lower-case, with dot: ".step", ".stp", ...
  BackendFactory factory;               ///< empty when not built
  std::string unavailable_reason;       ///< why it is not built, e.g. "vendor SDK not found"
};

class Registry {
 public:
  /// Adds or replaces a backend by name.
  void add(BackendInfo info);
  /// Marks a known backend as not built, with the reason shown to the user.
  void add_unavailable(const std::string& name, const std::string& description, const std::string& reason);

  bool has(const std::string& name) const;
  bool available(const std::string& name) const;
  std::vector<std::string> names() const;
  const BackendInfo& info(const std::string& name) const;

  /// The backend that reads a file of this extension by default; CadError(UnknownBackend) if none.
  std::string backend_for_path(const std::string& path) const;
  /// Loads with the named backend. Throws CadError(UnknownBackend / BackendUnavailable / ...).
  std::unique_ptr<Model> load(const std::string& name, const Source& source) const;

 private:
  std::vector<BackendInfo> backends_;
};

}  // namespace semimesh::cad
