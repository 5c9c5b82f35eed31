// Text inside an XML attribute or element: the five characters XML reserves escaped.
#pragma once

#include <string>

namespace semimesh::io {

inline std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace semimesh::io
