// The pieces of JSON text that report.json, `semimesh check --json` and `semimesh cad-info --json`
// write by hand (the documents are small and flat; no JSON library is needed).
#pragma once

#include <string>

namespace semimesh::io {

/// A JSON string literal of `text` (RFC 8259 section 7: quote, backslash and every control
/// character escaped; bytes >= 0x80 pass through, so UTF-8 stays UTF-8).
std::string json_string(const std::string& text);

/// A JSON number in its shortest round-trip form; null for infinity and NaN (JSON has neither).
std::string json_number(double value);

}  // namespace semimesh::io
