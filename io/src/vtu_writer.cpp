#include "atomic_folder.hpp"
#include "xml_escape.hpp"
#include "zlib_stream.hpp"

#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace semimesh::io {
namespace {

constexpr std::size_t kBlockBytes = 1 << 16;
constexpr std::size_t kBatchBlocks = 64;  // compressed together, in parallel

/// One data array in VTK's compressed layout (vtkZLibDataCompressor, header_type UInt64): the
/// number of blocks, the block size, the size of a partial last block (0 if it is full), each
/// block's compressed size, then the blocks, each its own zlib stream. Blocks go to the file as
/// they are compressed; the header, reserved first (its length follows from the array's raw size,
/// known in advance), is filled in at the end.
class CompressedArray {
 public:
  CompressedArray(AtomicFile& out, std::size_t raw_bytes, Content content)
      : out_(out), raw_bytes_(raw_bytes), header_at_(out.bytes_written()), content_(content) {
    const std::vector<std::uint64_t> placeholder(3 + (raw_bytes + kBlockBytes - 1) / kBlockBytes, 0);
    out.write(placeholder.data(), placeholder.size() * sizeof(std::uint64_t));
  }
  void add(const void* data, std::size_t bytes) {
    const char* c = static_cast<const char*>(data);
    while (bytes) {
      if (batch_.empty() || batch_.back().size() == kBlockBytes) {
        if (batch_.size() == kBatchBlocks) flush();
        batch_.emplace_back();
        batch_.back().reserve(kBlockBytes);
      }
      const std::size_t take = std::min(bytes, kBlockBytes - batch_.back().size());
      batch_.back().append(c, take);
      c += take, bytes -= take, total_ += take;
    }
  }
  template <typename T>
  void add_value(T v) {
    add(&v, sizeof v);
  }
  void finish() {
    flush();
    if (total_ != raw_bytes_)
      throw std::logic_error("VTU writer: an array of " + std::to_string(raw_bytes_) + " bytes got " +
                             std::to_string(total_));
    std::vector<std::uint64_t> header{sizes_.size(), kBlockBytes, total_ % kBlockBytes};
    header.insert(header.end(), sizes_.begin(), sizes_.end());
    out_.overwrite(header_at_, header.data(), header.size() * sizeof(std::uint64_t));
  }

 private:
  void flush() {
    for (const std::string& z : zlib_compress_blocks(batch_, content_)) {
      sizes_.push_back(z.size());
      out_.write(z.data(), z.size());
    }
    batch_.clear();
  }
  AtomicFile& out_;
  std::size_t raw_bytes_, header_at_;
  Content content_;
  std::vector<std::string> batch_;
  std::vector<std::uint64_t> sizes_;
  std::size_t total_ = 0;
};

/// What one .vtu holds: the volume elements or not, the boundary faces of every group, of none or of
/// one, and the points: every node (point i = node i), or only the nodes those cells use.
struct Piece {
  static constexpr int kAllGroups = -1, kNoGroup = -2;
  bool volume = true;
  int group = kAllGroups;
  std::vector<mesh::NodeId> points;    ///< the nodes that are points, in order; empty: every node
  std::vector<std::int64_t> point_of;  ///< [nodes] point index of a node, -1 if not a point; empty: identity

  bool takes(const mesh::BoundaryFace& f) const { return group == kAllGroups || group == int(f.group); }
};

/// The piece of one boundary group: its faces, with only the nodes they use, in node order.
Piece group_piece(const mesh::Mesh& m, int group) {
  Piece piece{false, group, {}, std::vector<std::int64_t>(m.num_nodes(), -1)};
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    if (piece.takes(m.boundary_faces()[b]))
      for (mesh::NodeId n : m.boundary_face_nodes(b)) piece.point_of[n] = 0;
  for (mesh::NodeId n = 0; n < m.num_nodes(); ++n)
    if (piece.point_of[n] >= 0) {
      piece.point_of[n] = static_cast<std::int64_t>(piece.points.size());
      piece.points.push_back(n);
    }
  return piece;
}

/// The arrays of one piece, each produced value by value by a generator that takes an emitter.
/// Connectivity and offsets are Int32 (half the bytes, faster to compress) unless a value could
/// overflow it.
struct Arrays {
  const mesh::Mesh& m;
  const EquispacedNodes& x;
  const Piece& piece;
  std::array<const std::vector<int>*, 7> permutation{};  // vtk_from_canonical per shape
  std::size_t num_cells = 0, connectivity_size = 0;

  Arrays(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const Piece& p) : m(mesh), x(nodes), piece(p) {
    for (auto shape : {ho::Shape::Triangle, ho::Shape::Quadrilateral, ho::Shape::Tetrahedron, ho::Shape::Pyramid,
                       ho::Shape::Prism, ho::Shape::Hexahedron})
      permutation[static_cast<int>(shape)] = &vtk_from_canonical(shape, m.order());
    if (piece.volume)
      for (const auto& el : m.elements()) ++num_cells, connectivity_size += cell_size(el.shape);
    for (const auto& bf : m.boundary_faces())
      if (piece.takes(bf)) ++num_cells, connectivity_size += cell_size(bf.shape);
  }
  std::size_t cell_size(ho::Shape shape) const { return permutation[static_cast<int>(shape)]->size(); }
  std::size_t num_points() const { return piece.points.empty() ? m.num_nodes() : piece.points.size(); }
  std::int64_t point(mesh::NodeId n) const { return piece.point_of.empty() ? std::int64_t(n) : piece.point_of[n]; }
  bool int32_connectivity() const { return num_points() <= std::size_t(INT32_MAX); }
  bool int32_offsets() const { return connectivity_size <= std::size_t(INT32_MAX); }

  /// f(shape, boundary group or -1, region or -1) per cell: elements, then faces.
  template <typename F>
  void each_cell(F f) const {
    if (piece.volume)
      for (const mesh::Element& el : m.elements()) f(el.shape, -1, int(el.region));
    for (const mesh::BoundaryFace& bf : m.boundary_faces())
      if (piece.takes(bf)) f(bf.shape, int(bf.group), -1);
  }
  /// f(shape, canonical node ids) per cell, in each_cell's order.
  template <typename F>
  void each_cell_nodes(F f) const {
    std::vector<mesh::NodeId> ids;
    if (piece.volume)
      for (std::size_t e = 0; e < m.elements().size(); ++e) {
        m.element_nodes(e, ids);
        f(m.elements()[e].shape, ids);
      }
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
      if (piece.takes(m.boundary_faces()[b])) f(m.boundary_faces()[b].shape, m.boundary_face_nodes(b));
  }
  template <typename Emit>
  void points(Emit emit) const {
    if (piece.points.empty())
      for (const auto& p : x.all()) emit(p);
    for (mesh::NodeId n : piece.points) emit(x[n]);
  }
  template <typename Emit, typename EndCell>
  void connectivity(Emit emit, EndCell end_cell) const {
    each_cell_nodes([&](ho::Shape shape, const std::vector<mesh::NodeId>& canonical) {
      for (int k : *permutation[static_cast<int>(shape)]) emit(point(canonical[k]));
      end_cell();
    });
  }
  template <typename Emit>
  void offsets(Emit emit) const {
    std::int64_t offset = 0;
    each_cell([&](ho::Shape shape, int, int) { emit(offset += cell_size(shape)); });
  }
  template <typename Emit>
  void types(Emit emit) const {
    each_cell([&](ho::Shape shape, int, int) { emit(static_cast<std::uint8_t>(vtk_cell_type(shape))); });
  }
  template <typename Emit>
  void boundary_group(Emit emit) const {
    each_cell([&](ho::Shape, int group, int) { emit(std::int32_t(group)); });
  }
  template <typename Emit>
  void regions(Emit emit) const {
    each_cell([&](ho::Shape, int, int region) { emit(std::int32_t(region)); });
  }
};

void header(AtomicFile& out, const Arrays& a, bool compressed) {
  out.print("<?xml version=\"1.0\"?>\n");
  out.print("<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\" header_type=\"UInt64\"{}>\n"
            "<UnstructuredGrid>\n",
            compressed ? " compressor=\"vtkZLibDataCompressor\"" : "");
  out.print("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", a.num_points(), a.num_cells);
}

std::string region_legend(const mesh::Mesh& m) {
  std::string s;
  const auto names = m.region_names();
  for (std::size_t r = 0; r < names.size(); ++r) s += (r ? " " : "") + std::to_string(r) + "=" + names[r];
  for (std::size_t k; (k = s.find("--")) != std::string::npos;) s[k] = '_';  // "--" would end the comment
  return s;
}

/// The DataArray elements of the file; `format` is "ascii" or "appended", with `offset(k)` the
/// attribute text written for array k (appended only).
template <typename Offset>
void data_arrays(AtomicFile& out, const Arrays& a, const char* format, Offset offset) {
  const char* connectivity = a.int32_connectivity() ? "Int32" : "Int64";
  const char* offsets = a.int32_offsets() ? "Int32" : "Int64";
  out.print("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"{}\"", format);
  offset(0);
  out.print("</Points>\n<Cells>\n<DataArray type=\"{}\" Name=\"connectivity\" format=\"{}\"", connectivity, format);
  offset(1);
  out.print("<DataArray type=\"{}\" Name=\"offsets\" format=\"{}\"", offsets, format);
  offset(2);
  out.print("<DataArray type=\"UInt8\" Name=\"types\" format=\"{}\"", format);
  offset(3);
  out.print("</Cells>\n<CellData>\n<DataArray type=\"Int32\" Name=\"boundary_group\" format=\"{}\"", format);
  offset(4);
  out.print("<!-- region: {} -->\n<DataArray type=\"Int32\" Name=\"region\" format=\"{}\"", region_legend(a.m), format);
  offset(5);
  out.print("</CellData>\n</Piece>\n</UnstructuredGrid>\n");
}

void write_ascii(AtomicFile& out, const Arrays& a) {
  header(out, a, false);
  // Each array's values follow its opening tag.
  data_arrays(out, a, "ascii", [&](int k) {
    out.print(">\n");
    bool first = true;
    switch (k) {
      case 0:
        a.points([&](const Eigen::Vector3d& p) { out.print("{} {} {}\n", p[0], p[1], p[2]); });
        break;
      case 1:
        a.connectivity([&](std::int64_t v) { out.print(first ? "{}" : " {}", v), first = false; },
                       [&] { out.print("\n"), first = true; });
        break;
      case 2: a.offsets([&](std::int64_t v) { out.print("{}\n", v); }); break;
      case 3: a.types([&](std::uint8_t v) { out.print("{}\n", v); }); break;
      case 4: a.boundary_group([&](std::int32_t v) { out.print("{}\n", v); }); break;
      case 5: a.regions([&](std::int32_t v) { out.print("{}\n", v); }); break;
    }
    out.print("</DataArray>\n");
  });
  out.print("</VTKFile>\n");
}

/// Appended raw data: the XML first, each array's offset a fixed-width placeholder filled in when
/// the arrays before it are written (their compressed sizes are known only then). Progress: one
/// step per array.
void write_compressed(AtomicFile& out, const Arrays& a, const ProgressCallback& progress) {
  static const char* const kNames[] = {"points", "connectivity", "offsets", "types", "boundary_group", "region"};
  constexpr int kOffsetWidth = 20;  // any uint64 in decimal; VTK reads the padded number
  header(out, a, true);
  std::size_t placeholder[6];
  data_arrays(out, a, "appended", [&](int k) {
    out.print(" offset=\"");
    placeholder[k] = out.bytes_written();
    out.print("{:<{}}\"/>\n", 0, kOffsetWidth);
  });
  out.print("<AppendedData encoding=\"raw\">\n_");
  const std::size_t base = out.bytes_written();
  auto array = [&](int k, std::size_t raw_bytes, auto fill) {
    if (progress) progress(k / 6.0, kNames[k]);
    const std::string offset = fmt::format("{:<{}}", out.bytes_written() - base, kOffsetWidth);
    out.overwrite(placeholder[k], offset.data(), offset.size());
    CompressedArray c(out, raw_bytes, k == 0 ? Content::Doubles : Content::Integers);
    fill(c);
    c.finish();
  };
  array(0, a.num_points() * sizeof(Eigen::Vector3d), [&](CompressedArray& c) {
    if (a.piece.points.empty())
      c.add(a.x.all().data(), a.x.all().size() * sizeof(Eigen::Vector3d));
    else
      a.points([&](const Eigen::Vector3d& p) { c.add(p.data(), sizeof(Eigen::Vector3d)); });
  });
  const bool int32_ids = a.int32_connectivity(), int32_offsets = a.int32_offsets();
  array(1, a.connectivity_size * (int32_ids ? 4 : 8), [&](CompressedArray& c) {
    a.connectivity([&](std::int64_t v) { int32_ids ? c.add_value(std::int32_t(v)) : c.add_value(v); },
                   [] {});
  });
  array(2, a.num_cells * (int32_offsets ? 4 : 8), [&](CompressedArray& c) {
    a.offsets([&](std::int64_t v) { int32_offsets ? c.add_value(std::int32_t(v)) : c.add_value(v); });
  });
  array(3, a.num_cells, [&](CompressedArray& c) { a.types([&](std::uint8_t v) { c.add_value(v); }); });
  array(4, a.num_cells * 4,
        [&](CompressedArray& c) { a.boundary_group([&](std::int32_t v) { c.add_value(v); }); });
  array(5, a.num_cells * 4,
        [&](CompressedArray& c) { a.regions([&](std::int32_t v) { c.add_value(v); }); });
  out.print("\n</AppendedData>\n</VTKFile>\n");
  if (progress) progress(1.0, "");
}

// A file name made of the group's name: characters other than letters, digits, '-' and '_' become '_'.
std::string file_name_part(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return s;
}

}  // namespace

void write_vtu(const mesh::Mesh& mesh, const std::string& path, VtuEncoding encoding,
               const ProgressCallback& progress) {
  write_vtu(mesh, EquispacedNodes(mesh), path, encoding, progress);
}

void write_vtu(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path, VtuEncoding encoding,
               const ProgressCallback& progress) {
  const Piece everything;  // volume elements, every boundary face, every node
  const Arrays arrays(mesh, nodes, everything);
  AtomicFile out(path);
  if (encoding == VtuEncoding::Ascii)
    write_ascii(out, arrays);
  else
    write_compressed(out, arrays, progress);
  out.commit();
}

std::string vtm_piece_folder(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / p.stem()).string();
}

void write_vtm(const mesh::Mesh& mesh, const std::string& path, const ProgressCallback& progress) {
  write_vtm(mesh, EquispacedNodes(mesh), path, progress);
}

void write_vtm(const mesh::Mesh& m, const EquispacedNodes& nodes, const std::string& path,
               const ProgressCallback& progress) {
  const std::string folder_path = vtm_piece_folder(path);
  const std::string folder_name = std::filesystem::path(folder_path).filename().string();
  struct Block {
    std::string name, file;
    Piece piece;
  };
  std::vector<Block> blocks = {{"volume", "volume.vtu", Piece{true, Piece::kNoGroup, {}, {}}}};
  for (std::size_t g = 0; g < m.group_names().size(); ++g)
    blocks.push_back({m.group_names()[g], fmt::format("boundary{}_{}.vtu", g, file_name_part(m.group_names()[g])),
                      group_piece(m, static_cast<int>(g))});

  AtomicFolder folder(folder_path);
  AtomicFile index(path);
  index.print("<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
              "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<vtkMultiBlockDataSet>\n");
  // The volume holds most of the cells and every node: it gets the first half of the progress.
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const double from = b == 0 ? 0.0 : 0.5 + 0.5 * (b - 1) / double(blocks.size() - 1);
    const double to = b == 0 ? 0.5 : 0.5 + 0.5 * b / double(blocks.size() - 1);
    AtomicFile piece(folder.file(blocks[b].file));
    const ProgressCallback part = progress_part(progress, from, to);
    write_compressed(piece, Arrays(m, nodes, blocks[b].piece),
                     part ? [&](double f, const std::string& step) {
                       part(f, step.empty() ? blocks[b].name : blocks[b].name + ": " + step);
                     } : ProgressCallback{});
    piece.commit();
    index.print("  <DataSet index=\"{}\" name=\"{}\" file=\"{}/{}\"/>\n", b, xml_escape(blocks[b].name),
                xml_escape(folder_name), blocks[b].file);
  }
  index.print("</vtkMultiBlockDataSet>\n</VTKFile>\n");
  folder.commit(index);
  if (progress) progress(1.0, "");
}

}  // namespace semimesh::io
