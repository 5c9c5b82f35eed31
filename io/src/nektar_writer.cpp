#include "nektar_numbering.hpp"
#include "region_labels.hpp"
#include "xml_escape.hpp"
#include "zlib_stream.hpp"

#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <future>
#include <map>
#include <stdexcept>
#include <thread>

namespace semimesh::io {
namespace {

// LibUtilities::PointsType values (LibUtilities/Foundations/PointsType.h), for compressed CURVED.
constexpr std::int64_t kPolyEvenlySpaced = 17;
constexpr std::int64_t kNodalTriEvenlySpaced = 24;
const char* const kCompressed = "COMPRESSED=\"B64Z-LittleEndian\" BITSIZE=\"64\"";

const ho::Shape kVolumeShapes[] = {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism,
                                   ho::Shape::Hexahedron};

/// "0-3,7,9-10": Nektar++'s range syntax inside X[...].
std::string id_ranges(const std::vector<std::size_t>& ids) {
  std::string s;
  for (std::size_t i = 0; i < ids.size();) {
    std::size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1) ++j;
    s += (s.empty() ? "" : ",") + std::to_string(ids[i]) + (j > i ? "-" + std::to_string(ids[j]) : "");
    i = j + 1;
  }
  return s;
}

/// Lattice (i, j) -> canonical index of an equispaced tri (frame f0 f1 f2) or quad of order p.
std::map<std::pair<int, int>, int> lattice_index(int num_vertices, int p) {
  const ho::Shape shape = num_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
  const Eigen::MatrixX3d ref = ho::reference_nodes(shape, p, ho::NodeSet::Equispaced);
  std::map<std::pair<int, int>, int> at;
  for (int n = 0; n < ref.rows(); ++n) {
    double u = ref(n, 0), v = ref(n, 1);
    if (num_vertices == 4) u = (u + 1) / 2, v = (v + 1) / 2;
    at[{static_cast<int>(std::lround(u * p)), static_cast<int>(std::lround(v * p))}] = n;
  }
  return at;
}

/// Nektar's triangle point order as lattice points of the written frame w0 w1 w2.
std::vector<std::pair<int, int>> nodal_tri_lattice(int p) {
  std::vector<std::pair<int, int>> lattice{{0, 0}, {p, 0}, {0, p}};
  for (int i = 1; i < p; ++i) lattice.push_back({i, 0});
  for (int i = 1; i < p; ++i) lattice.push_back({p - i, i});
  for (int i = 1; i < p; ++i) lattice.push_back({0, p - i});
  for (int j = 1; j < p; ++j)
    for (int i = 1; i + j < p; ++i) lattice.push_back({i, j});
  return lattice;
}

/// Canonical indices (stored frame f0 f1 f2) of Nektar's triangle points when the face is written
/// as (f_s, f_s+1, f_s+2): one order per rotation s.
std::array<std::vector<int>, 3> tri_orders(int p) {
  const auto at = lattice_index(3, p);
  std::array<std::vector<int>, 3> orders;
  for (int s = 0; s < 3; ++s)
    for (const auto& [i, j] : nodal_tri_lattice(p)) {
      const int w[3] = {p - i - j, i, j};  // barycentric (times p) on w0 w1 w2
      int f[3];
      for (int k = 0; k < 3; ++k) f[(k + s) % 3] = w[k];
      orders[s].push_back(at.at({f[1], f[2]}));
    }
  return orders;
}

std::vector<int> quad_order(int p) {
  const auto at = lattice_index(4, p);
  std::vector<int> order;
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i <= p; ++i) order.push_back(at.at({i, j}));
  return order;
}

/// f(i) for i in [0, n) on every hardware thread; f(i) may write only entries of its own i.
template <typename F>
void parallel_for(std::size_t n, F f) {
  const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::future<void>> workers;
  for (std::size_t t = 1; t < threads; ++t)
    workers.push_back(std::async(std::launch::async, [&, t] {
      for (std::size_t i = n * t / threads; i < n * (t + 1) / threads; ++i) f(i);
    }));
  for (std::size_t i = 0; i < n / threads; ++i) f(i);
  for (auto& w : workers) w.get();  // rethrows a worker's exception
}

/// Everything the sections need, computed once.
struct Geometry {
  const mesh::Mesh& m;
  const EquispacedNodes& node;  // positions written
  NektarNumbering numbering;
  std::array<std::vector<int>, 3> tri_point_order;
  std::vector<int> quad_point_order;
  // Only curved entities get a CURVED entry (as NekMesh writes): a straight one is the same
  // geometry without it, and the straight-sided far field is most of a mesh.
  std::vector<char> edge_curved, face_curved;

  Geometry(const mesh::Mesh& mesh, const EquispacedNodes& nodes) : m(mesh), node(nodes), numbering(number_for_nektar(mesh)) {
    if (m.order() < 2) return;
    tri_point_order = tri_orders(m.order()), quad_point_order = quad_order(m.order());
    tri_reference_ = ho::reference_nodes(ho::Shape::Triangle, m.order(), ho::NodeSet::Equispaced);
    quad_reference_ = ho::reference_nodes(ho::Shape::Quadrilateral, m.order(), ho::NodeSet::Equispaced);
    face_curved.resize(m.faces().size());
    parallel_for(m.faces().size(), [&](std::size_t f) {
      const bool tri = num_face_vertices(f) == 3;
      thread_local std::vector<mesh::NodeId> ids;
      if (m.order() < (tri ? 3 : 2)) return;
      m.face_nodes(f, ids);
      face_curved[f] = !on_linear_map(tri ? ho::Shape::Triangle : ho::Shape::Quadrilateral, ids);
    });
    edge_curved.resize(m.edges().size());
    parallel_for(m.edges().size(), [&](std::size_t e) {
      thread_local std::vector<mesh::NodeId> ids;
      m.edge_nodes(e, ids);
      edge_curved[e] = !on_linear_map(ho::Shape::Segment, ids);
    });
    // A curved face needs P+1 points on each of its edges, straight or not (Tri/QuadGeom::v_FillGeom).
    for (std::size_t f = 0; f < m.faces().size(); ++f)
      if (face_curved[f])
        for (int k = 0; k < num_face_vertices(f); ++k) edge_curved[m.faces()[f].edges[k]] = 1;
  }

  /// True if every node sits where the straight-sided (affine / bilinear) entity puts it.
  bool on_linear_map(ho::Shape shape, const std::vector<mesh::NodeId>& ids) const {
    for (mesh::NodeId id : ids) __builtin_prefetch(node[id].data());  // scattered: the misses overlap
    const Eigen::MatrixX3d& ref = reference(shape);
    const int nv = shape == ho::Shape::Segment ? 2 : ho::num_vertices(shape);
    Eigen::Vector3d x[4];
    for (int k = 0; k < nv; ++k) x[k] = node[shape == ho::Shape::Segment ? ids[k ? ids.size() - 1 : 0] : ids[k]];
    const double tolerance = 1e-12 * std::max(1.0, (x[1] - x[0]).cwiseAbs().maxCoeff() + (x[nv - 1] - x[0]).cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      Eigen::Vector3d want;
      if (shape == ho::Shape::Segment) {
        const double t = double(i) / (ids.size() - 1);
        want = (1 - t) * x[0] + t * x[1];
      } else if (shape == ho::Shape::Triangle) {
        want = (1 - ref(i, 0) - ref(i, 1)) * x[0] + ref(i, 0) * x[1] + ref(i, 1) * x[2];
      } else {
        const double s = (ref(i, 0) + 1) / 2, t = (ref(i, 1) + 1) / 2;
        want = (1 - s) * (1 - t) * x[0] + s * (1 - t) * x[1] + s * t * x[2] + (1 - s) * t * x[3];
      }
      if ((node[ids[i]] - want).cwiseAbs().maxCoeff() > tolerance) return false;
    }
    return true;
  }
  const Eigen::MatrixX3d& reference(ho::Shape shape) const {
    static const Eigen::MatrixX3d none;
    if (shape == ho::Shape::Segment) return none;
    return shape == ho::Shape::Triangle ? tri_reference_ : quad_reference_;
  }
  Eigen::MatrixX3d tri_reference_, quad_reference_;

  int num_face_vertices(std::size_t f) const { return m.faces()[f].num_vertices; }

  /// How far the written vertices of a face are rotated from the stored ones.
  int written_rotation(std::size_t f) const {
    const auto w = written_face_vertices(m, numbering, f);
    int s = 0;
    while (m.faces()[f].vertices[s] != w[0]) ++s;
    return s;
  }

  /// Edge ids of a face as written.
  std::array<std::int64_t, 4> face_edges(std::size_t f) const {
    const int n = num_face_vertices(f), s = written_rotation(f);
    std::array<std::int64_t, 4> e{};
    for (int k = 0; k < n; ++k) e[k] = m.faces()[f].edges[(k + s) % n];  // edge k joins stored vertices k, k+1
    return e;
  }

  /// Face ids of an element in Nektar's local face order.
  std::array<std::int64_t, 6> element_faces(std::size_t e) const {
    const auto& el = m.elements()[e];
    const std::array<mesh::NodeId, 8> v = nektar_element_vertices(m, numbering, e);
    const auto& gmsh_faces = ho::faces(el.shape);
    const auto& nek_faces = nektar_faces(el.shape);
    std::array<std::int64_t, 6> out{};
    for (std::size_t k = 0; k < nek_faces.size(); ++k) {
      std::array<mesh::NodeId, 4> want{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode, mesh::kNoNode};
      for (std::size_t i = 0; i < nek_faces[k].size(); ++i) want[i] = v[nek_faces[k][i]];
      std::sort(want.begin(), want.end());
      out[k] = -1;
      for (std::size_t g = 0; g < gmsh_faces.size() && out[k] < 0; ++g) {
        std::array<mesh::NodeId, 4> have{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode, mesh::kNoNode};
        for (std::size_t i = 0; i < gmsh_faces[g].size(); ++i) have[i] = el.vertices[gmsh_faces[g][i]];
        std::sort(have.begin(), have.end());
        if (have == want) out[k] = el.faces[g];
      }
      if (out[k] < 0) throw std::logic_error("Nektar++ XML: element " + std::to_string(e) + " lost a face");
    }
    return out;
  }

  /// Curved nodes of a face, in the order written.
  template <typename Emit>
  void face_nodes_written(std::size_t f, Emit emit) const {
    face_slots_written(f, [&](int, mesh::NodeId id) { emit(id); });
  }
  /// The same with each node's position k in the face's canonical node list (its slot in
  /// mesh::node_layout of the face's shape).
  template <typename Emit>
  void face_slots_written(std::size_t f, Emit emit) const {
    thread_local std::vector<mesh::NodeId> ids;
    m.face_nodes(f, ids);
    if (num_face_vertices(f) == 3) {
      for (int k : tri_point_order[written_rotation(f)]) emit(k, ids[k]);
    } else {
      for (int k : quad_point_order) emit(k, ids[k]);
    }
  }
  bool face_is_curved(std::size_t f) const { return m.order() >= 2 && face_curved[f]; }
  bool edge_is_curved(std::size_t e) const { return m.order() >= 2 && edge_curved[e]; }
  bool any_curved() const {
    return std::count(edge_curved.begin(), edge_curved.end(), 1) + std::count(face_curved.begin(), face_curved.end(), 1);
  }
};

void write_plain(AtomicFile& out, const Geometry& g) {
  const mesh::Mesh& m = g.m;
  auto vid = [&](mesh::NodeId v) { return g.numbering.vertex_id(v); };
  out.print("    <VERTEX>\n");
  for (std::size_t i = 0; i < g.numbering.vertex_node.size(); ++i) {
    const auto& x = g.node[g.numbering.vertex_node[i]];
    out.print("      <V ID=\"{}\">{} {} {}</V>\n", i, x[0], x[1], x[2]);
  }
  out.print("    </VERTEX>\n    <EDGE>\n");
  for (std::size_t e = 0; e < m.edges().size(); ++e)
    out.print("      <E ID=\"{}\">{} {}</E>\n", e, vid(m.edges()[e].vertices[0]), vid(m.edges()[e].vertices[1]));
  out.print("    </EDGE>\n    <FACE>\n");
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const int n = g.num_face_vertices(f);
    const auto e = g.face_edges(f);
    const char tag = n == 3 ? 'T' : 'Q';
    out.print("      <{} ID=\"{}\">", tag, f);
    for (int k = 0; k < n; ++k) out.print(" {}", e[k]);
    out.print(" </{}>\n", tag);
  }
  out.print("    </FACE>\n    <ELEMENT>\n");
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const ho::Shape shape = m.elements()[e].shape;
    const char tag = nektar_tag(shape);
    const auto faces = g.element_faces(e);
    out.print("      <{} ID=\"{}\">", tag, e);
    for (std::size_t k = 0; k < nektar_faces(shape).size(); ++k) out.print(" {}", faces[k]);
    out.print(" </{}>\n", tag);
  }
  out.print("    </ELEMENT>\n");
  if (!g.any_curved()) return;
  out.print("    <CURVED>\n");
  std::size_t curve = 0;
  auto point = [&](const Eigen::Vector3d& x) { out.print(" {} {} {}", x[0], x[1], x[2]); };
  for (std::size_t e = 0; e < m.edges().size(); ++e) {
    if (!g.edge_is_curved(e)) continue;
    out.print("      <E ID=\"{}\" EDGEID=\"{}\" NUMPOINTS=\"{}\" TYPE=\"PolyEvenlySpaced\">", curve++, e, m.order() + 1);
    for (mesh::NodeId id : m.edge_nodes(e)) point(g.node[id]);
    out.print(" </E>\n");
  }
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    if (!g.face_is_curved(f)) continue;
    const bool tri = g.num_face_vertices(f) == 3;
    out.print("      <F ID=\"{}\" FACEID=\"{}\" NUMPOINTS=\"{}\" TYPE=\"{}\">", curve++, f,
              tri ? g.tri_point_order[0].size() : g.quad_point_order.size(),
              tri ? "NodalTriEvenlySpaced" : "PolyEvenlySpaced");
    g.face_nodes_written(f, [&](mesh::NodeId id) { point(g.node[id]); });
    out.print(" </F>\n");
  }
  out.print("    </CURVED>\n");
}

/// <TAG attributes COMPRESSED...>base64(zlib(records))</TAG>
template <typename Fill>
void compressed_block(AtomicFile& out, const std::string& indent, const std::string& tag, Fill fill,
                      bool attributes = true, Content content = Content::Integers) {
  out.print("{}<{}{}{}>", indent, tag, attributes ? " " : "", attributes ? kCompressed : "");
  Base64Out text(out);
  ZlibStream z([&](const char* data, std::size_t bytes) { text.add(data, bytes); }, content);
  fill(z);
  z.finish();
  text.finish();
  out.print("</{}>\n", tag);
}

void write_compressed(AtomicFile& out, const Geometry& g) {
  const mesh::Mesh& m = g.m;
  auto vid = [&](mesh::NodeId v) { return g.numbering.vertex_id(v); };
  using I = std::int64_t;
  auto put_point = [](ZlibStream& z, I id, const Eigen::Vector3d& x) {
    z.add_value(id);
    z.add(x.data(), 3 * sizeof(double));
  };
  out.print("    ");
  compressed_block(out, "", "VERTEX", [&](ZlibStream& z) {
    for (std::size_t i = 0; i < g.numbering.vertex_node.size(); ++i) put_point(z, I(i), g.node[g.numbering.vertex_node[i]]);
  }, true, Content::Doubles);
  out.print("    ");
  compressed_block(out, "", "EDGE", [&](ZlibStream& z) {
    for (std::size_t e = 0; e < m.edges().size(); ++e) {
      const I rec[3] = {I(e), I(vid(m.edges()[e].vertices[0])), I(vid(m.edges()[e].vertices[1]))};
      z.add(rec, sizeof rec);
    }
  });
  out.print("    <FACE>\n");
  for (int n : {3, 4}) {
    bool any = false;
    for (const auto& face : m.faces()) any = any || face.num_vertices == n;
    if (!any) continue;
    compressed_block(out, "      ", n == 3 ? "T" : "Q", [&](ZlibStream& z) {
      for (std::size_t f = 0; f < m.faces().size(); ++f) {
        if (g.num_face_vertices(f) != n) continue;
        const auto e = g.face_edges(f);
        z.add_value(I(f));
        z.add(e.data(), n * sizeof(I));
      }
    });
  }
  out.print("    </FACE>\n    <ELEMENT>\n");
  for (ho::Shape shape : kVolumeShapes) {
    bool any = false;
    for (const auto& el : m.elements()) any = any || el.shape == shape;
    if (!any) continue;
    const std::size_t nf = nektar_faces(shape).size();
    compressed_block(out, "      ", std::string(1, nektar_tag(shape)), [&](ZlibStream& z) {
      for (std::size_t e = 0; e < m.elements().size(); ++e) {
        if (m.elements()[e].shape != shape) continue;
        const auto faces = g.element_faces(e);
        z.add_value(I(e));
        z.add(faces.data(), nf * sizeof(I));
      }
    });
  }
  out.print("    </ELEMENT>\n");
  if (!g.any_curved()) return;

  // CURVED: MeshCurvedInfo records {id, entityid, npoints, ptid, ptoffset, ptype} for edges and
  // faces, then DATAPOINTS: INDEX (curve point -> unique point) and POINTS (MeshVertex records).
  // Curves share their points through INDEX: every edge/face node is stored once. INDEX cannot be
  // left out: MeshGraphIOXmlCompressed::v_ReadCurves requires it and reads every point through it.
  // A node's point id is the order of its first sight in INDEX; POINTS replays the same walk and
  // writes each node at its first sight. The ids are kept per vertex, edge and face, not per node
  // (4 bytes a node): a curved face's edges are all curved, so its vertices and edge nodes are
  // first seen along the edges (an edge's inner nodes one after the other), and its own nodes,
  // seen nowhere else, take the next ids in the order written.
  constexpr std::uint32_t kUnseen = 0xffffffffu;
  std::vector<std::uint32_t> vertex_point(g.numbering.vertex_node.size(), kUnseen);
  std::vector<std::uint32_t> edge_point(m.edges().size(), kUnseen), face_point(m.faces().size(), kUnseen);
  std::uint32_t points = 0;
  auto vertex = [&](mesh::NodeId id) {
    std::uint32_t& point = vertex_point[g.numbering.vertex_id(id)];
    if (point == kUnseen) point = points++;
    return point;
  };
  const int inner = m.order() - 1;
  // f(node, point id) along INDEX's walk.
  auto each_curved_node = [&](auto f) {
    std::vector<mesh::NodeId> ids;
    for (std::size_t e = 0; e < m.edges().size(); ++e) {
      if (!g.edge_is_curved(e)) continue;
      m.edge_nodes(e, ids);
      f(ids.front(), vertex(ids.front()));
      if (edge_point[e] == kUnseen) edge_point[e] = points, points += inner;
      for (int j = 0; j < inner; ++j) f(ids[j + 1], edge_point[e] + j);
      f(ids.back(), vertex(ids.back()));
    }
    for (std::size_t face = 0; face < m.faces().size(); ++face) {
      if (!g.face_is_curved(face)) continue;
      const mesh::Face& entity = m.faces()[face];
      const auto& slots =
          mesh::node_layout(entity.num_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral, m.order()).slots;
      if (face_point[face] == kUnseen)
        face_point[face] = points, points += mesh::face_interior_count(entity.num_vertices, m.order());
      std::uint32_t own = face_point[face];
      g.face_slots_written(face, [&](int k, mesh::NodeId id) {
        const mesh::NodeSlot& slot = slots[k];
        if (slot.kind == mesh::NodeSlot::Vertex) return f(id, vertex(id));
        if (slot.kind == mesh::NodeSlot::Face) return f(id, own++);
        const std::uint32_t edge = entity.edges[slot.local];
        if (edge_point[edge] == kUnseen)
          throw std::logic_error("Nektar++ XML: curved face " + std::to_string(face) + " has a straight edge");
        f(id, edge_point[edge] + slot.slot[(entity.edge_reversed >> slot.local) & 1u]);
      });
    }
  };
  const I p = m.order();
  I total = 0;
  out.print("    <CURVED {}>\n", kCompressed);
  compressed_block(out, "      ", "E", [&](ZlibStream& z) {
    I id = 0;
    for (std::size_t e = 0; e < m.edges().size(); ++e) {
      if (!g.edge_is_curved(e)) continue;
      const I rec[6] = {id++, I(e), p + 1, 0, total, kPolyEvenlySpaced};
      z.add(rec, sizeof rec);
      total += p + 1;
    }
  }, false);
  compressed_block(out, "      ", "F", [&](ZlibStream& z) {
    I id = 0;
    for (std::size_t f = 0; f < m.faces().size(); ++f) {
      if (!g.face_is_curved(f)) continue;
      const bool tri = g.num_face_vertices(f) == 3;
      const I n = tri ? I(g.tri_point_order[0].size()) : I(g.quad_point_order.size());
      const I rec[6] = {id++, I(f), n, 0, total, tri ? kNodalTriEvenlySpaced : kPolyEvenlySpaced};
      z.add(rec, sizeof rec);
      total += n;
    }
  }, false);
  out.print("      <DATAPOINTS ID=\"0\">\n");
  compressed_block(out, "        ", "INDEX", [&](ZlibStream& z) {
    each_curved_node([&](mesh::NodeId, std::uint32_t point) { z.add_value(I(point)); });
  }, false);
  compressed_block(out, "        ", "POINTS", [&](ZlibStream& z) {
    std::uint32_t next = 0;
    each_curved_node([&](mesh::NodeId id, std::uint32_t point) {
      if (point == next) put_point(z, I(next), g.node[id]), ++next;
    });
  }, false, Content::Doubles);
  out.print("      </DATAPOINTS>\n    </CURVED>\n");
}

struct ElementComposite {
  std::string region;
  char tag;
  std::vector<std::size_t> elements;
};

/// One composite per (region, element letter), in region then letter order.
std::vector<ElementComposite> element_composites(const mesh::Mesh& m) {
  std::map<std::pair<int, char>, std::vector<std::size_t>> groups;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    groups[{int(m.elements()[e].region), nektar_tag(m.elements()[e].shape)}].push_back(e);
  const auto names = detail::region_labels(m);  // not the boundary groups' names
  std::vector<ElementComposite> out;
  for (auto& [key, ids] : groups) out.push_back({names[key.first], key.second, std::move(ids)});
  return out;
}

void write_composites(AtomicFile& out, const mesh::Mesh& m) {
  out.print("    <COMPOSITE>\n");
  const auto composites = element_composites(m);
  std::string domain;
  for (std::size_t c = 0; c < composites.size(); ++c) {
    domain += (c ? "," : "") + std::to_string(c);
    out.print("      <C ID=\"{}\" NAME=\"{}\"> {}[{}] </C>\n", c, xml_escape(composites[c].region),
              composites[c].tag, id_ranges(composites[c].elements));
  }
  std::vector<std::vector<std::size_t>> group_faces(m.group_names().size());
  for (const auto& bf : m.boundary_faces()) group_faces[bf.group].push_back(bf.face);
  for (std::size_t g = 0; g < group_faces.size(); ++g) {
    std::sort(group_faces[g].begin(), group_faces[g].end());
    out.print("      <C ID=\"{}\" NAME=\"{}\"> F[{}] </C>\n", composites.size() + g, xml_escape(m.group_names()[g]),
              id_ranges(group_faces[g]));
  }
  out.print("    </COMPOSITE>\n    <DOMAIN> C[{}] </DOMAIN>\n  </GEOMETRY>\n", domain);
  out.print("  <EXPANSIONS>\n");
  for (std::size_t c = 0; c < composites.size(); ++c)
    out.print("    <E COMPOSITE=\"C[{}]\" NUMMODES=\"{}\" TYPE=\"MODIFIED\" FIELDS=\"u\" />\n", c, m.order() + 1);
  out.print("  </EXPANSIONS>\n");
}

}  // namespace

void write_nektar_xml(const mesh::Mesh& mesh, const std::string& path, NektarEncoding encoding) {
  write_nektar_xml(mesh, EquispacedNodes(mesh), path, encoding);
}

void write_nektar_xml(const mesh::Mesh& mesh, const EquispacedNodes& nodes, const std::string& path,
                      NektarEncoding encoding) {
  const Geometry geometry(mesh, nodes);
  AtomicFile out(path);
  out.print("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<NEKTAR>\n  <GEOMETRY DIM=\"3\" SPACE=\"3\">\n");
  if (encoding == NektarEncoding::Plain)
    write_plain(out, geometry);
  else
    write_compressed(out, geometry);
  write_composites(out, geometry.m);
  out.print("</NEKTAR>\n");
  out.commit();
}

}  // namespace semimesh::io
