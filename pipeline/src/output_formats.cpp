#include "semimesh/pipeline/output_formats.hpp"

#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <stdexcept>

namespace semimesh::pipeline {

using Paths = std::vector<std::string>;
using io::MshEncoding, io::MshVersion;

const std::vector<OutputFormat>& output_formats() {
  static const std::vector<OutputFormat> formats = {
      {"msh41", ".msh", "",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback& progress) {
         io::write_msh(m, p, MshVersion::V41, MshEncoding::Ascii, progress);
         return Paths{p};
       }},
      {"msh41-binary", ".msh", ".bin.msh",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback& progress) {
         io::write_msh(m, p, MshVersion::V41, MshEncoding::Binary, progress);
         return Paths{p};
       }},
      {"msh22", ".msh", ".v22.msh",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback& progress) {
         io::write_msh(m, p, MshVersion::V22, MshEncoding::Ascii, progress);
         return Paths{p};
       }},
      {"vtu", ".vtu", "",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback& progress) {
         io::write_vtu(m, p, io::VtuEncoding::CompressedBinary, progress);
         return Paths{p};
       }},
      {"vtu-ascii", ".vtu", ".ascii.vtu",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback&) {
         io::write_vtu(m, p, io::VtuEncoding::Ascii);
         return Paths{p};
       }},
      {"vtm", ".vtm", "",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback& progress) {
         io::write_vtm(m, p, progress);
         return Paths{p, io::vtm_piece_folder(p)};
       }},
      {"nektar", ".xml", "",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback&) {
         io::write_nektar_xml(m, p, io::NektarEncoding::Compressed);
         return Paths{p};
       }},
      {"nektar-xml", ".xml", ".plain.xml",
       [](const mesh::Mesh& m, const std::string& p, const ProgressCallback&) {
         io::write_nektar_xml(m, p, io::NektarEncoding::Plain);
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
