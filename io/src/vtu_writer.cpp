#include "atomic_folder.hpp"
#include "xml_escape.hpp"
#include "zlib_stream.hpp"

#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <cstdint>
#include <functional>

namespace semimesh::io {
namespace {

constexpr std::size_t kBlockBytes = 1 << 16;
constexpr std::size_t kBatchBlocks = 64;  // compressed together, in parallel

/// One data array in VTK's compressed layout (vtkZLibDataCompressor, header_type UInt64): the
/// number of blocks, the block size, the size of a partial last block (0 if it is full), each
/// block's compressed size, then the blocks, each its own zlib stream.
class CompressedArray {
 public:
  explicit CompressedArray(Content content = Content::Integers) : content_(content) {}
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
  std::string finish() {
    flush();
    std::string out;
    auto put = [&](std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
    put(sizes_.size());
    put(kBlockBytes);
    put(total_ % kBlockBytes);
    for (std::uint64_t s : sizes_) put(s);
    return out + data_;
  }

 private:
  void flush() {
    for (const std::string& z : zlib_compress_blocks(batch_, content_)) {
      sizes_.push_back(z.size());
      data_ += z;
    }
    batch_.clear();
  }
  Content content_;
  std::vector<std::string> batch_;
  std::string data_;
  std::vector<std::uint64_t> sizes_;
  std::size_t total_ = 0;
};

/// What one .vtu holds: the volume elements or not, the boundary faces of every group, of none or of
/// one, and the points: every node (point i = node i), or only the nodes those cells use.
struct Piece {
  static constexpr int kAllGroups = -1, kNoGroup = -2;
  bool volume = true;
  int group = kAllGroups;
  std::vector<mesh::NodeId> points;        ///< the nodes that are points, in order; empty: every node
  std::vector<std::int64_t> point_of;      ///< [nodes] point index of a node, -1 if not a point; empty: identity

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

/// The arrays of the file, each produced value by value by a generator that takes an emitter.
struct Arrays {
  const mesh::Mesh& m;
  const EquispacedNodes& x;
  const Piece& piece;

  std::size_t num_points() const { return piece.points.empty() ? m.num_nodes() : piece.points.size(); }
  std::size_t num_cells() const {
    std::size_t n = piece.volume ? m.elements().size() : 0;
    for (const auto& bf : m.boundary_faces()) n += piece.takes(bf) ? 1 : 0;
    return n;
  }
  std::int64_t point(mesh::NodeId n) const { return piece.point_of.empty() ? n : piece.point_of[n]; }
  /// f(shape, canonical node ids, boundary group or -1, region or -1) per cell: elements, then faces.
  template <typename F>
  void each_cell(F f) const {
    std::vector<mesh::NodeId> ids;
    if (piece.volume)
      for (std::size_t e = 0; e < m.elements().size(); ++e) {
        m.element_nodes(e, ids);
        f(m.elements()[e].shape, ids, -1, int(m.elements()[e].region));
      }
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
      if (piece.takes(m.boundary_faces()[b]))
        f(m.boundary_faces()[b].shape, m.boundary_face_nodes(b), int(m.boundary_faces()[b].group), -1);
  }

  void points(const std::function<void(double)>& emit) const {
    if (piece.points.empty())
      for (const auto& p : x.all()) emit(p[0]), emit(p[1]), emit(p[2]);
    for (mesh::NodeId n : piece.points) {
      const auto& p = x[n];
      emit(p[0]), emit(p[1]), emit(p[2]);
    }
  }
  void connectivity(const std::function<void(std::int64_t)>& emit, bool line_per_cell,
                    const std::function<void()>& end_line) const {
    each_cell([&](ho::Shape shape, const std::vector<mesh::NodeId>& canonical, int, int) {
      for (int k : vtk_from_canonical(shape, m.order())) emit(point(canonical[k]));
      if (line_per_cell) end_line();
    });
  }
  void offsets(const std::function<void(std::int64_t)>& emit) const {
    std::int64_t offset = 0;
    each_cell([&](ho::Shape shape, const std::vector<mesh::NodeId>&, int, int) {
      emit(offset += vtk_from_canonical(shape, m.order()).size());
    });
  }
  void types(const std::function<void(std::uint8_t)>& emit) const {
    each_cell([&](ho::Shape shape, const std::vector<mesh::NodeId>&, int, int) {
      emit(static_cast<std::uint8_t>(vtk_cell_type(shape)));
    });
  }
  void boundary_group(const std::function<void(std::int32_t)>& emit) const {
    each_cell([&](ho::Shape, const std::vector<mesh::NodeId>&, int group, int) { emit(group); });
  }
  void regions(const std::function<void(std::int32_t)>& emit) const {
    each_cell([&](ho::Shape, const std::vector<mesh::NodeId>&, int, int region) { emit(region); });
  }
};

void header(AtomicFile& out, const Arrays& a, bool compressed) {
  out.print("<?xml version=\"1.0\"?>\n");
  out.print("<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\" header_type=\"UInt64\"{}>\n"
            "<UnstructuredGrid>\n",
            compressed ? " compressor=\"vtkZLibDataCompressor\"" : "");
  out.print("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", a.num_points(), a.num_cells());
}

std::string region_legend(const mesh::Mesh& m) {
  std::string s;
  const auto names = m.region_names();
  for (std::size_t r = 0; r < names.size(); ++r) s += (r ? " " : "") + std::to_string(r) + "=" + names[r];
  for (std::size_t k; (k = s.find("--")) != std::string::npos;) s[k] = '_';  // "--" would end the comment
  return s;
}

void write_ascii(AtomicFile& out, const Arrays& a) {
  const mesh::Mesh& m = a.m;
  header(out, a, false);
  out.print("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  int component = 0;
  a.points([&](double v) {
    if (++component % 3)
      out.print("{} ", v);
    else
      out.print("{}\n", v);
  });
  out.print("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  bool first = true;
  a.connectivity([&](std::int64_t v) { out.print(first ? "{}" : " {}", v), first = false; }, true,
                 [&] { out.print("\n"), first = true; });
  out.print("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  a.offsets([&](std::int64_t v) { out.print("{}\n", v); });
  out.print("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  a.types([&](std::uint8_t v) { out.print("{}\n", v); });
  out.print("</DataArray>\n</Cells>\n<CellData>\n");
  out.print("<DataArray type=\"Int32\" Name=\"boundary_group\" format=\"ascii\">\n");
  a.boundary_group([&](std::int32_t v) { out.print("{}\n", v); });
  out.print("</DataArray>\n<!-- region: {} -->\n<DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n",
            region_legend(m));
  a.regions([&](std::int32_t v) { out.print("{}\n", v); });
  out.print("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

// Progress: one step per array.
void write_compressed(AtomicFile& out, const Arrays& a, const ProgressCallback& progress) {
  std::vector<std::string> data(6);
  const auto done = [&](int arrays, const char* next) {
    if (progress) progress(arrays / 6.0, next);
  };
  done(0, "points");
  {
    CompressedArray c(Content::Doubles);
    a.points([&](double v) { c.add_value(v); });
    data[0] = c.finish();
  }
  done(1, "connectivity");
  {
    CompressedArray c;
    a.connectivity([&](std::int64_t v) { c.add_value(v); }, false, [] {});
    data[1] = c.finish();
  }
  done(2, "offsets");
  {
    CompressedArray c;
    a.offsets([&](std::int64_t v) { c.add_value(v); });
    data[2] = c.finish();
  }
  done(3, "types");
  {
    CompressedArray c;
    a.types([&](std::uint8_t v) { c.add_value(v); });
    data[3] = c.finish();
  }
  done(4, "boundary_group");
  {
    CompressedArray c;
    a.boundary_group([&](std::int32_t v) { c.add_value(v); });
    data[4] = c.finish();
  }
  done(5, "region");
  {
    CompressedArray c;
    a.regions([&](std::int32_t v) { c.add_value(v); });
    data[5] = c.finish();
  }
  done(6, "");
  std::size_t offset[7] = {0};
  for (int k = 0; k < 6; ++k) offset[k + 1] = offset[k] + data[k].size();
  header(out, a, true);
  out.print("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n"
            "</Points>\n<Cells>\n", offset[0]);
  out.print("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"{}\"/>\n", offset[1]);
  out.print("<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"{}\"/>\n", offset[2]);
  out.print("<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"{}\"/>\n</Cells>\n<CellData>\n",
            offset[3]);
  out.print("<DataArray type=\"Int32\" Name=\"boundary_group\" format=\"appended\" offset=\"{}\"/>\n", offset[4]);
  out.print("<!-- region: {} -->\n<DataArray type=\"Int32\" Name=\"region\" format=\"appended\" offset=\"{}\"/>\n",
            region_legend(a.m), offset[5]);
  out.print("</CellData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");
  for (const auto& d : data) out.write(d.data(), d.size());
  out.print("\n</AppendedData>\n</VTKFile>\n");
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
  const Arrays arrays{mesh, nodes, everything};
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
    write_compressed(piece, Arrays{m, nodes, blocks[b].piece},
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
