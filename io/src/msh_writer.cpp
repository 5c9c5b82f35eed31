
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/gmsh_types.hpp"
#include "semimesh/io/msh.hpp"

#include "region_labels.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <stdexcept>

namespace semimesh::io {
namespace {

using Box = std::array<double, 6>;  // min x y z, max x y z

Box empty_box() {
  const double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, inf, -inf, -inf, -inf};
}

void grow(Box& box, const Eigen::Vector3d& x) {
  for (int k = 0; k < 3; ++k) {
    box[k] = std::min(box[k], x[k]);
    box[k + 3] = std::max(box[k + 3], x[k]);
  }
}

/// Numbers written as ASCII (space separated, one record a line) or as raw little-endian binary
/// (MSH 4.1 binary: int for tags of entities and types, size_t for counts and node/element tags).
class MshOut {
 public:
  MshOut(AtomicFile& file, bool binary) : f_(file), binary_(binary) {}
  bool binary() const { return binary_; }
  void text(const std::string& s) { f_.write(s); }
  void size(std::size_t v) { binary_ ? f_.write_value(v) : ascii(v); }
  void integer(int v) { binary_ ? f_.write_value(v) : ascii(v); }
  void real(double v) { binary_ ? f_.write_value(v) : ascii(v); }
  void end_record() {
    if (!binary_) f_.write("\n", 1);
    first_ = true;
  }
  /// An element's record: its tag, then its nodes' tags (ids + 1); in binary one write of the
  /// whole record, not one per number.
  void element(std::size_t tag, const std::vector<mesh::NodeId>& ids) {
    if (!binary_) {
      size(tag);
      for (mesh::NodeId id : ids) size(id + std::size_t{1});
      return end_record();
    }
    record_.resize(ids.size() + 1);
    record_[0] = tag;
    for (std::size_t i = 0; i < ids.size(); ++i) record_[i + 1] = ids[i] + std::size_t{1};
    f_.write(record_.data(), record_.size() * sizeof(std::size_t));
  }
  /// Closes a binary section's data (Gmsh expects a newline before $End...).
  void end_section(const char* name) { f_.print("{}$End{}\n", binary_ ? "\n" : "", name); }

 private:
  template <typename T>
  void ascii(T v) {
    f_.print(first_ ? "{}" : " {}", v);
    first_ = false;
  }
  AtomicFile& f_;
  bool binary_;
  bool first_ = true;
  std::vector<std::size_t> record_;
};

/// Physical tags are unique across dimensions (PyFR keys groups by tag alone): boundary group g
/// has tag g + 1, volume region r tag G + volume_tag[r].
struct Tags {
  std::size_t groups = 0;
  std::vector<std::string> regions;
  std::vector<int> volume_tag;  // per region: entity tag 1.., or 0 if the region has no element
  int num_volumes = 0;
  int volume_physical(int region) const { return static_cast<int>(groups) + volume_tag[region]; }
};

Tags make_tags(const mesh::Mesh& m) {
  Tags t;
  t.groups = m.group_names().size();
  t.regions = detail::region_labels(m);  // unique physical names, ignoring case (PyFR)
  std::vector<char> used(t.regions.size(), 0);
  for (std::size_t e = 0; e < m.elements().size(); ++e) used[m.elements()[e].region] = 1;
  t.volume_tag.assign(t.regions.size(), 0);
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    if (used[r]) t.volume_tag[r] = ++t.num_volumes;
  return t;
}

void write_physical_names(AtomicFile& out, const mesh::Mesh& m, const Tags& t) {
  const auto& groups = m.group_names();
  out.print("$PhysicalNames\n{}\n", groups.size() + t.num_volumes);
  for (std::size_t g = 0; g < groups.size(); ++g) out.print("2 {} \"{}\"\n", g + 1, groups[g]);
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    if (t.volume_tag[r]) out.print("3 {} \"{}\"\n", t.volume_physical(static_cast<int>(r)), t.regions[r]);
  out.print("$EndPhysicalNames\n");
}

void write_entity(MshOut& out, int tag, const Box& b, int physical) {
  out.integer(tag);
  for (double x : b) out.real(x);
  out.size(1);
  out.integer(physical);
  out.size(0);
  out.end_record();
}

/// Binary $Nodes data: the node tags 1..n, then the coordinates straight from the array (three
/// doubles a node, as Gmsh reads them), each in pieces of a few MB.
void write_binary_nodes(AtomicFile& file, const std::vector<Eigen::Vector3d>& x, ProgressCounter& counter) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "a node is three packed doubles");
  constexpr std::size_t kPiece = std::size_t{1} << 18;
  std::vector<std::size_t> tags;
  tags.reserve(kPiece);
  for (std::size_t first = 0; first < x.size(); first += kPiece) {
    tags.clear();
    for (std::size_t i = first; i < std::min(x.size(), first + kPiece); ++i) tags.push_back(i + 1);
    file.write(tags.data(), tags.size() * sizeof(std::size_t));
  }
  for (std::size_t first = 0; first < x.size(); first += kPiece) {
    const std::size_t count = std::min(kPiece, x.size() - first);
    file.write(x[first].data(), count * sizeof(Eigen::Vector3d));
    counter.add(count);
    counter.report_if_due();
  }
}

constexpr int kNumShapes = static_cast<int>(ho::Shape::Hexahedron) + 1;  // the values of ho::Shape

/// The elements of each (region, shape), in element order, at [region * kNumShapes + shape]: one
/// pass over the elements, not one per block.
std::vector<std::vector<std::size_t>> elements_by_region_and_shape(const mesh::Mesh& m, std::size_t num_regions) {
  std::vector<std::vector<std::size_t>> out(num_regions * kNumShapes);
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    out[m.elements()[e].region * kNumShapes + static_cast<int>(m.elements()[e].shape)].push_back(e);
  return out;
}

const ho::Shape kVolumeShapes[] = {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism, ho::Shape::Hexahedron};
const ho::Shape kFaceShapes[] = {ho::Shape::Triangle, ho::Shape::Quadrilateral};

void write_v41(AtomicFile& file, const mesh::Mesh& m, const EquispacedNodes& x, bool binary, ProgressCounter& counter) {
  const Tags t = make_tags(m);
  MshOut out(file, binary);
  file.print("$MeshFormat\n4.1 {} 8\n", binary ? 1 : 0);
  if (binary) {
    file.write_value(int{1});
    file.write("\n");
  }
  file.print("$EndMeshFormat\n");
  write_physical_names(file, m, t);

  const std::size_t num_groups = t.groups;
  std::vector<Box> group_box(num_groups, empty_box());
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    for (mesh::NodeId id : m.boundary_face_nodes(b)) grow(group_box[m.boundary_faces()[b].group], x[id]);
  Box all = empty_box();
  for (const auto& point : x.all()) grow(all, point);
  if (m.nodes().empty()) all = {0, 0, 0, 0, 0, 0};
  file.print("$Entities\n");
  for (std::size_t count : {std::size_t{0}, std::size_t{0}, num_groups, std::size_t(t.num_volumes)}) out.size(count);
  out.end_record();
  for (std::size_t g = 0; g < num_groups; ++g)
    write_entity(out, static_cast<int>(g + 1), group_box[g][0] <= group_box[g][3] ? group_box[g] : all,
                 static_cast<int>(g + 1));
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    if (t.volume_tag[r]) write_entity(out, t.volume_tag[r], all, t.volume_physical(static_cast<int>(r)));
  out.end_section("Entities");

  // Every node goes in one block classified on the first volume (or the first surface).
  const std::size_t n = m.num_nodes();
  file.print("$Nodes\n");
  for (std::size_t v : {std::size_t(n ? 1 : 0), n, std::size_t(n ? 1 : 0), n}) out.size(v);
  out.end_record();
  if (n) {
    out.integer(t.num_volumes ? 3 : 2);
    out.integer(1);
    out.integer(0);
    out.size(n);
    out.end_record();
    if (binary) {
      write_binary_nodes(file, x.all(), counter);
    } else {
      for (std::size_t i = 1; i <= n; ++i) out.size(i), out.end_record();
      for (const auto& p : x.all()) {
        out.real(p[0]), out.real(p[1]), out.real(p[2]), out.end_record();
        counter.add();
        counter.report_if_due();
      }
    }
  }
  out.end_section("Nodes");

  // Blocks: (region, shape) volumes, then (group, shape) boundary faces; each element streamed.
  struct Block {
    int dim, entity, region_or_group;
    ho::Shape shape;
    std::size_t count;
  };
  std::vector<Block> blocks;
  const std::vector<std::vector<std::size_t>> elements_of = elements_by_region_and_shape(m, t.regions.size());
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    for (ho::Shape s : kVolumeShapes)
      if (const std::size_t count = elements_of[r * kNumShapes + static_cast<int>(s)].size())
        blocks.push_back({3, t.volume_tag[r], static_cast<int>(r), s, count});
  for (std::size_t g = 0; g < num_groups; ++g)
    for (ho::Shape s : kFaceShapes) {
      std::size_t count = 0;
      for (const auto& bf : m.boundary_faces()) count += bf.shape == s && bf.group == g;
      if (count) blocks.push_back({2, static_cast<int>(g + 1), static_cast<int>(g), s, count});
    }
  const std::size_t total = m.elements().size() + m.boundary_faces().size();
  file.print("$Elements\n");
  for (std::size_t v : {blocks.size(), total, std::size_t(total ? 1 : 0), total}) out.size(v);
  out.end_record();
  std::size_t tag = 0;
  std::vector<mesh::NodeId> ids;
  for (const Block& b : blocks) {
    out.integer(b.dim);
    out.integer(b.entity);
    out.integer(gmsh_element_type(b.shape, m.order()));
    out.size(b.count);
    out.end_record();
    if (b.dim == 3) {
      for (std::size_t e : elements_of[b.region_or_group * kNumShapes + static_cast<int>(b.shape)]) {
        m.element_nodes(e, ids);
        out.element(++tag, ids);
        counter.add();
        counter.report_if_due();
      }
    } else {
      for (std::size_t f = 0; f < m.boundary_faces().size(); ++f) {
        const auto& bf = m.boundary_faces()[f];
        if (bf.shape == b.shape && bf.group == b.region_or_group) {
          out.element(++tag, m.boundary_face_nodes(f));
          counter.add();
          counter.report_if_due();
        }
      }
    }
  }
  out.end_section("Elements");
}

void write_v22(AtomicFile& out, const mesh::Mesh& m, const EquispacedNodes& x, ProgressCounter& counter) {
  const Tags t = make_tags(m);
  out.print("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  write_physical_names(out, m, t);
  out.print("$Nodes\n{}\n", m.num_nodes());
  std::size_t id = 0;
  for (const auto& p : x.all()) {
    out.print("{} {} {} {}\n", ++id, p[0], p[1], p[2]);
    counter.add();
    counter.report_if_due();
  }
  out.print("$EndNodes\n$Elements\n{}\n", m.elements().size() + m.boundary_faces().size());
  std::size_t tag = 0;
  std::vector<mesh::NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    const int region = int(m.elements()[e].region);
    out.print("{} {} 2 {} {}", ++tag, gmsh_element_type(m.elements()[e].shape, m.order()), t.volume_physical(region),
              t.volume_tag[region]);
    for (mesh::NodeId n : ids) out.print(" {}", n + 1);
    out.print("\n");
    counter.add();
    counter.report_if_due();
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    const auto& bf = m.boundary_faces()[b];
    out.print("{} {} 2 {} {}", ++tag, gmsh_element_type(bf.shape, m.order()), bf.group + 1, bf.group + 1);
    for (mesh::NodeId n : m.boundary_face_nodes(b)) out.print(" {}", n + 1);
    out.print("\n");
    counter.add();
    counter.report_if_due();
  }
  out.print("$EndElements\n");
}

}  // namespace

void write_msh(const mesh::Mesh& mesh, const std::string& path, MshVersion version, MshEncoding encoding,
               const ProgressCallback& progress) {
  write_msh(mesh, EquispacedNodes(mesh), path, version, encoding, progress);
}

void write_msh(const mesh::Mesh& m, const EquispacedNodes& nodes, const std::string& path, MshVersion version,
               MshEncoding encoding, const ProgressCallback& progress) {
  gmsh_element_type(ho::Shape::Tetrahedron, m.order());  // rejects unsupported orders early
  if (version == MshVersion::V22 && encoding == MshEncoding::Binary)
    throw std::invalid_argument("MSH 2.2 is written as ASCII only (use MSH 4.1 for binary): " + path);
  AtomicFile out(path);
  // Progress: one item per node and per element or boundary face written.
  ProgressCounter counter(progress, m.num_nodes() + m.elements().size() + m.boundary_faces().size());
  if (version == MshVersion::V41)
    write_v41(out, m, nodes, encoding == MshEncoding::Binary, counter);
  else
    write_v22(out, m, nodes, counter);
  out.commit();
  counter.finish();
}

}  // namespace semimesh::io
