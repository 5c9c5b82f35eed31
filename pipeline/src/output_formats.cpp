#include "semimesh/pipeline/output_formats.hpp"

#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <stdexcept>

namespace semimesh::pipeline {

const std::vector<OutputFormat>& output_formats() {
  static const std::vector<OutputFormat> formats = {
      {"msh41", ".msh", "", [](const mesh::Mesh& m, const std::string& p) { io::write_msh(m, p, io::MshVersion::V41); }},
      {"msh41-binary", ".msh", ".bin.msh",
       [](const mesh::Mesh& m, const std::string& p) {
         io::write_msh(m, p, io::MshVersion::V41, io::MshEncoding::Binary);
       }},
      {"msh22", ".msh", ".v22.msh", [](const mesh::Mesh& m, const std::string& p) { io::write_msh(m, p, io::MshVersion::V22); }},
      {"vtu", ".vtu", "",
       [](const mesh::Mesh& m, const std::string& p) { io::write_vtu(m, p, io::VtuEncoding::CompressedBinary); }},
      {"vtu-ascii", ".vtu", ".ascii.vtu",
       [](const mesh::Mesh& m, const std::string& p) { io::write_vtu(m, p, io::VtuEncoding::Ascii); }},
      {"nektar", ".xml", "",
       [](const mesh::Mesh& m, const std::string& p) { io::write_nektar_xml(m, p, io::NektarEncoding::Compressed); }},
      {"nektar-xml", ".xml", ".plain.xml",
       [](const mesh::Mesh& m, const std::string& p) { io::write_nektar_xml(m, p, io::NektarEncoding::Plain); }},
  };
  return formats;
}

const OutputFormat& output_format(const std::string& name) {
  for (const OutputFormat& f : output_formats())
    if (f.name == name) return f;
  throw std::invalid_argument("unknown output format '" + name + "'");
}

}  // namespace semimesh::pipeline
