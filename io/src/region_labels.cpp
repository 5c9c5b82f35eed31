#include "region_labels.hpp"

#include <algorithm>
#include <cctype>

namespace semimesh::io::detail {

std::vector<std::string> region_labels(const mesh::Mesh& m) {
  const auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
  };
  std::vector<std::string> labels = m.region_names();
  for (std::string& r : labels)
    for (const std::string& g : m.group_names())
      if (lower(r) == lower(g)) r += "_volume";
  return labels;
}

}  // namespace semimesh::io::detail
