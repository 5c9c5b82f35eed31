// The mesh file formats `semimesh run` writes: one row each (config name, file extension, writer),
// used by the config's output.formats, the output paths and the write stage.
#pragma once

#include "semimesh/io/equispaced.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <string>
#include <vector>

namespace semimesh::pipeline {

struct OutputFormat {
  std::string name;       ///< as in output.formats
  std::string extension;  ///< of BASENAME.EXT
  std::string extension_when_shared;  ///< used instead when another requested format has the same extension
  /// Writes the file at `path` atomically from the mesh's equispaced node positions (computed once
  /// for every format); progress: per part of the file, where the writer has parts. Returns what it
  /// wrote: the file, and for vtm also its folder of pieces.
  std::vector<std::string> (*write)(const mesh::Mesh& mesh, const io::EquispacedNodes& nodes, const std::string& path,
                                    const ProgressCallback& progress);
};

/// Every format, in the order docs/config.md lists them.
const std::vector<OutputFormat>& output_formats();

/// The format named `name`; throws std::invalid_argument for an unknown name.
const OutputFormat& output_format(const std::string& name);

}  // namespace semimesh::pipeline
