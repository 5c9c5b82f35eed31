#include "zlib_stream.hpp"

#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <algorithm>
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

/// The arrays of the file, each produced value by value by a generator that takes an emitter.
struct Arrays {
  const mesh::Mesh& m;
  const EquispacedNodes& x;

  void points(const std::function<void(double)>& emit) const {
    for (const auto& p : x.all()) emit(p[0]), emit(p[1]), emit(p[2]);
  }
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
  void connectivity(const std::function<void(std::int64_t)>& emit, bool line_per_cell,
                    const std::function<void()>& end_line) const {
    cells([&](ho::Shape shape, const std::vector<mesh::NodeId>& canonical) {
      for (int k : vtk_from_canonical(shape, m.order())) emit(canonical[k]);
      if (line_per_cell) end_line();
    });
  }
  void offsets(const std::function<void(std::int64_t)>& emit) const {
    std::int64_t offset = 0;
    for (const auto& el : m.elements()) emit(offset += vtk_from_canonical(el.shape, m.order()).size());
    for (const auto& bf : m.boundary_faces()) emit(offset += vtk_from_canonical(bf.shape, m.order()).size());
  }
  void types(const std::function<void(std::uint8_t)>& emit) const {
    for (const auto& el : m.elements()) emit(static_cast<std::uint8_t>(vtk_cell_type(el.shape)));
    for (const auto& bf : m.boundary_faces()) emit(static_cast<std::uint8_t>(vtk_cell_type(bf.shape)));
  }
  void boundary_group(const std::function<void(std::int32_t)>& emit) const {
    for (std::size_t e = 0; e < m.elements().size(); ++e) emit(-1);
    for (const auto& bf : m.boundary_faces()) emit(bf.group);
  }
  void regions(const std::function<void(std::int32_t)>& emit) const {
    for (std::size_t e = 0; e < m.elements().size(); ++e) emit(int(m.elements()[e].region));
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) emit(-1);
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

void write_ascii(AtomicFile& out, const Arrays& a) {
  const mesh::Mesh& m = a.m;
  header(out, m, false);
  out.print("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const auto& p : a.x.all()) out.print("{} {} {}\n", p[0], p[1], p[2]);
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

void write_compressed(AtomicFile& out, const Arrays& a) {
  std::vector<std::string> data(6);
  {
    CompressedArray c(Content::Doubles);
    a.points([&](double v) { c.add_value(v); });
    data[0] = c.finish();
  }
  {
    CompressedArray c;
    a.connectivity([&](std::int64_t v) { c.add_value(v); }, false, [] {});
    data[1] = c.finish();
  }
  {
    CompressedArray c;
    a.offsets([&](std::int64_t v) { c.add_value(v); });
    data[2] = c.finish();
  }
  {
    CompressedArray c;
    a.types([&](std::uint8_t v) { c.add_value(v); });
    data[3] = c.finish();
  }
  {
    CompressedArray c;
    a.boundary_group([&](std::int32_t v) { c.add_value(v); });
    data[4] = c.finish();
  }
  {
    CompressedArray c;
    a.regions([&](std::int32_t v) { c.add_value(v); });
    data[5] = c.finish();
  }
  std::size_t offset[7] = {0};
  for (int k = 0; k < 6; ++k) offset[k + 1] = offset[k] + data[k].size();
  header(out, a.m, true);
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

}  // namespace

void write_vtu(const mesh::Mesh& mesh, const std::string& path, VtuEncoding encoding) {
  write_vtu(mesh, EquispacedNodes(mesh), path, encoding);
}

void write_vtu(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path, VtuEncoding encoding) {
  const Arrays arrays{mesh, nodes};
  AtomicFile out(path);
  if (encoding == VtuEncoding::Ascii)
    write_ascii(out, arrays);
  else
    write_compressed(out, arrays);
  out.commit();
}

}  // namespace semimesh::io
