#include "zlib_stream.hpp"

#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
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
      : out_(out), content_(content), raw_bytes_(raw_bytes), header_at_(out.bytes_written()) {
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
  Content content_;
  std::size_t raw_bytes_, header_at_;
  std::vector<std::string> batch_;
  std::vector<std::uint64_t> sizes_;
  std::size_t total_ = 0;
};

/// The arrays of the file, each produced value by value by a generator that takes an emitter.
/// Connectivity and offsets are Int32 (half the bytes, faster to compress) unless a value could
/// overflow it.
struct Arrays {
  const mesh::Mesh& m;
  const EquispacedNodes& x;
  std::array<const std::vector<int>*, 7> permutation{};  // vtk_from_canonical per shape
  std::size_t num_cells = 0, connectivity_size = 0;

  Arrays(const mesh::Mesh& mesh, const EquispacedNodes& nodes) : m(mesh), x(nodes) {
    for (auto shape : {ho::Shape::Triangle, ho::Shape::Quadrilateral, ho::Shape::Tetrahedron, ho::Shape::Pyramid,
                       ho::Shape::Prism, ho::Shape::Hexahedron})
      permutation[static_cast<int>(shape)] = &vtk_from_canonical(shape, m.order());
    num_cells = m.elements().size() + m.boundary_faces().size();
    for (const auto& el : m.elements()) connectivity_size += cell_size(el.shape);
    for (const auto& bf : m.boundary_faces()) connectivity_size += cell_size(bf.shape);
  }
  std::size_t cell_size(ho::Shape shape) const { return permutation[static_cast<int>(shape)]->size(); }
  bool int32_connectivity() const { return m.num_nodes() <= std::size_t(INT32_MAX); }
  bool int32_offsets() const { return connectivity_size <= std::size_t(INT32_MAX); }

  template <typename Emit>
  void cells(Emit emit_cell) const {
    std::vector<mesh::NodeId> ids;
    for (std::size_t e = 0; e < m.elements().size(); ++e) {
      m.element_nodes(e, ids);
      emit_cell(m.elements()[e].shape, ids);
    }
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
      emit_cell(m.boundary_faces()[b].shape, m.boundary_face_nodes(b));
  }
  template <typename Emit, typename EndCell>
  void connectivity(Emit emit, EndCell end_cell) const {
    cells([&](ho::Shape shape, const std::vector<mesh::NodeId>& canonical) {
      for (int k : *permutation[static_cast<int>(shape)]) emit(canonical[k]);
      end_cell();
    });
  }
  template <typename Emit>
  void offsets(Emit emit) const {
    std::int64_t offset = 0;
    for (const auto& el : m.elements()) emit(offset += cell_size(el.shape));
    for (const auto& bf : m.boundary_faces()) emit(offset += cell_size(bf.shape));
  }
  template <typename Emit>
  void types(Emit emit) const {
    for (const auto& el : m.elements()) emit(static_cast<std::uint8_t>(vtk_cell_type(el.shape)));
    for (const auto& bf : m.boundary_faces()) emit(static_cast<std::uint8_t>(vtk_cell_type(bf.shape)));
  }
  template <typename Emit>
  void boundary_group(Emit emit) const {
    for (std::size_t e = 0; e < m.elements().size(); ++e) emit(std::int32_t{-1});
    for (const auto& bf : m.boundary_faces()) emit(std::int32_t(bf.group));
  }
  template <typename Emit>
  void regions(Emit emit) const {
    for (std::size_t e = 0; e < m.elements().size(); ++e) emit(std::int32_t(m.elements()[e].region));
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) emit(std::int32_t{-1});
  }
};

void header(AtomicFile& out, const mesh::Mesh& m, bool compressed) {
  out.print("<?xml version=\"1.0\"?>\n");
  out.print("<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\" header_type=\"UInt64\"{}>\n"
            "<UnstructuredGrid>\n",
            compressed ? " compressor=\"vtkZLibDataCompressor\"" : "");
  out.print("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", m.num_nodes(),
            m.elements().size() + m.boundary_faces().size());
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
  header(out, a.m, false);
  // Each array's values follow its opening tag.
  data_arrays(out, a, "ascii", [&](int k) {
    out.print(">\n");
    bool first = true;
    switch (k) {
      case 0:
        for (const auto& p : a.x.all()) out.print("{} {} {}\n", p[0], p[1], p[2]);
        break;
      case 1:
        a.connectivity([&](mesh::NodeId v) { out.print(first ? "{}" : " {}", v), first = false; },
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
/// the arrays before it are written (their compressed sizes are known only then).
void write_compressed(AtomicFile& out, const Arrays& a) {
  constexpr int kOffsetWidth = 20;  // any uint64 in decimal; VTK reads the padded number
  header(out, a.m, true);
  std::size_t placeholder[6];
  data_arrays(out, a, "appended", [&](int k) {
    out.print(" offset=\"");
    placeholder[k] = out.bytes_written();
    out.print("{:<{}}\"/>\n", 0, kOffsetWidth);
  });
  out.print("<AppendedData encoding=\"raw\">\n_");
  const std::size_t base = out.bytes_written();
  auto array = [&](int k, std::size_t raw_bytes, Content content, auto fill) {
    const std::string offset = fmt::format("{:<{}}", out.bytes_written() - base, kOffsetWidth);
    out.overwrite(placeholder[k], offset.data(), offset.size());
    CompressedArray c(out, raw_bytes, content);
    fill(c);
    c.finish();
  };
  const auto& points = a.x.all();
  array(0, points.size() * sizeof(Eigen::Vector3d), Content::Doubles,
        [&](CompressedArray& c) { c.add(points.data(), points.size() * sizeof(Eigen::Vector3d)); });
  const bool int32_ids = a.int32_connectivity(), int32_offsets = a.int32_offsets();
  array(1, a.connectivity_size * (int32_ids ? 4 : 8), Content::Integers, [&](CompressedArray& c) {
    a.connectivity([&](mesh::NodeId v) { int32_ids ? c.add_value(std::int32_t(v)) : c.add_value(std::int64_t(v)); },
                   [] {});
  });
  array(2, a.num_cells * (int32_offsets ? 4 : 8), Content::Integers, [&](CompressedArray& c) {
    a.offsets([&](std::int64_t v) { int32_offsets ? c.add_value(std::int32_t(v)) : c.add_value(v); });
  });
  array(3, a.num_cells, Content::Integers, [&](CompressedArray& c) { a.types([&](std::uint8_t v) { c.add_value(v); }); });
  array(4, a.num_cells * 4, Content::Integers,
        [&](CompressedArray& c) { a.boundary_group([&](std::int32_t v) { c.add_value(v); }); });
  array(5, a.num_cells * 4, Content::Integers,
        [&](CompressedArray& c) { a.regions([&](std::int32_t v) { c.add_value(v); }); });
  out.print("\n</AppendedData>\n</VTKFile>\n");
}

}  // namespace

void write_vtu(const mesh::Mesh& mesh, const std::string& path, VtuEncoding encoding) {
  write_vtu(mesh, EquispacedNodes(mesh), path, encoding);
}

void write_vtu(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path, VtuEncoding encoding) {
  const Arrays arrays(mesh, nodes);
  AtomicFile out(path);
  if (encoding == VtuEncoding::Ascii)
    write_ascii(out, arrays);
  else
    write_compressed(out, arrays);
  out.commit();
}

}  // namespace semimesh::io
