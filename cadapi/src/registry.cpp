#include "semimesh/cad/registry.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <cctype>

namespace semimesh::cad {

void Registry::add(BackendInfo info) {
  auto it = std::find_if(backends_.begin(), backends_.end(), [&](const BackendInfo& b) { return b.name == info.name; });
  if (it != backends_.end()) *it = std::move(info);
  else backends_.push_back(std::move(info));
}

void Registry::add_unavailable(const std::string& name, const std::string& description, const std::string& reason) {
  add(BackendInfo{name, description, {}, {}, reason});
}

bool Registry::has(const std::string& name) const {
  return std::any_of(backends_.begin(), backends_.end(), [&](const BackendInfo& b) { return b.name == name; });
}

bool Registry::available(const std::string& name) const { return has(name) && static_cast<bool>(info(name).factory); }

std::vector<std::string> Registry::names() const {
  std::vector<std::string> out;
  for (const auto& b : backends_) out.push_back(b.name);
  return out;
}

const BackendInfo& Registry::info(const std::string& name) const {
  for (const auto& b : backends_)
    if (b.name == name) return b;
  std::string list;
  for (const auto& b : backends_) list += (list.empty() ? "" : ", ") + b.name;
  throw CadError(CadError::Kind::UnknownBackend, "unknown CAD backend '" + name + "' (known: " + list + ")");
}

std::string Registry::backend_for_path(const std::string& path) const {
  auto dot = path.find_last_of('.');
  auto slash = path.find_last_of("/\\");
  bool in_file_name = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  std::string ext = in_file_name ? path.substr(dot) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const auto& b : backends_)
    if (std::find(b.extensions.begin(), b.extensions.end(), ext) != b.extensions.end()) return b.name;
  throw CadError(CadError::Kind::UnknownBackend,
                 "no CAD backend reads '" + path + "' (extension '" + ext + "'); name one with --backend");
}

std::unique_ptr<Model> Registry::load(const std::string& name, const Source& source) const {
  const BackendInfo& b = info(name);
  if (!b.factory)
    throw CadError(CadError::Kind::BackendUnavailable,
                   "backend '" + name + "' is not available in this build (" + b.unavailable_reason + ")");
  return b.factory(source);
}

}  // namespace semimesh::cad
