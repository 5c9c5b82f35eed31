#include "semimesh/pipeline/output_formats.hpp"

#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <stdexcept>

namespace semimesh::pipeline {

using Paths = std::vector<std::string>;
using io::MshEncoding, io::MshVersion;

const std::vector<OutputFormat>& output_formats() {
  using Mesh = mesh::Mesh;
  using Nodes = io::EquispacedNodes;
  using S = std::string;
  using Report = ProgressCallback;
  static const std::vector<OutputFormat> formats = {
      // Binary by default: a third of the ASCII bytes and no number formatting; ASCII on request
      // (PyFR reads ASCII only). "msh41-binary" is the same file, the name older configs use.
      {"msh41", ".msh", "",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_msh(m, x, p, MshVersion::V41, MshEncoding::Binary, progress);
         return Paths{p};
       }},
      {"msh41-ascii", ".msh", ".ascii.msh",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_msh(m, x, p, MshVersion::V41, MshEncoding::Ascii, progress);
         return Paths{p};
       }},
      {"msh41-binary", ".msh", ".bin.msh",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_msh(m, x, p, MshVersion::V41, MshEncoding::Binary, progress);
         return Paths{p};
       }},
      {"msh22", ".msh", ".v22.msh",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_msh(m, x, p, MshVersion::V22, MshEncoding::Ascii, progress);
         return Paths{p};
       }},
      {"vtu", ".vtu", "",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_vtu(m, x, p, io::VtuEncoding::CompressedBinary, progress);
         return Paths{p};
       }},
      {"vtu-ascii", ".vtu", ".ascii.vtu",
       [](const Mesh& m, const Nodes& x, const S& p, const Report&) {
         io::write_vtu(m, x, p, io::VtuEncoding::Ascii);
         return Paths{p};
       }},
      {"vtm", ".vtm", "",
       [](const Mesh& m, const Nodes& x, const S& p, const Report& progress) {
         io::write_vtm(m, x, p, progress);
         return Paths{p, io::vtm_piece_folder(p)};
       }},
      {"nektar", ".xml", "",
       [](const Mesh& m, const Nodes& x, const S& p, const Report&) {
         io::write_nektar_xml(m, x, p, io::NektarEncoding::Compressed);
         return Paths{p};
       }},
      {"nektar-xml", ".xml", ".plain.xml",
       [](const Mesh& m, const Nodes& x, const S& p, const Report&) {
         io::write_nektar_xml(m, x, p, io::NektarEncoding::Plain);
         return Paths{p};
       }},
  };
  return formats;
}

const OutputFormat& output_format(const std::string& name) {
  for (const OutputFormat& f : output_formats())
    if (f.name == name) return f;
  throw std::invalid_argument("unknown output format '" + name + "'");
}

}  // namespace semimesh::pipeline
