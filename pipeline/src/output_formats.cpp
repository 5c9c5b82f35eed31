#include "semimesh/pipeline/output_formats.hpp"

#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <stdexcept>

namespace semimesh::pipeline {

const std::vector<OutputFormat>& output_formats() {
  using Mesh = mesh::Mesh;
  using Nodes = io::EquispacedNodes;
  using S = std::string;
  static const std::vector<OutputFormat> formats = {
      {"msh41", ".msh", "",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_msh(m, x, p, io::MshVersion::V41); }},
      {"msh41-binary", ".msh", ".bin.msh",
       [](const Mesh& m, const Nodes& x, const S& p) {
         io::write_msh(m, x, p, io::MshVersion::V41, io::MshEncoding::Binary);
       }},
      {"msh22", ".msh", ".v22.msh",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_msh(m, x, p, io::MshVersion::V22); }},
      {"vtu", ".vtu", "",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_vtu(m, x, p, io::VtuEncoding::CompressedBinary); }},
      {"vtu-ascii", ".vtu", ".ascii.vtu",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_vtu(m, x, p, io::VtuEncoding::Ascii); }},
      {"nektar", ".xml", "",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_nektar_xml(m, x, p, io::NektarEncoding::Compressed); }},
      {"nektar-xml", ".xml", ".plain.xml",
       [](const Mesh& m, const Nodes& x, const S& p) { io::write_nektar_xml(m, x, p, io::NektarEncoding::Plain); }},
  };
  return formats;
}

const OutputFormat& output_format(const std::string& name) {
  for (const OutputFormat& f : output_formats())
    if (f.name == name) return f;
  throw std::invalid_argument("unknown output format '" + name + "'");
}

}  // namespace semimesh::pipeline
