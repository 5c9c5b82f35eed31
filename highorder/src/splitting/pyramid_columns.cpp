#include "semimesh/ho/splitting/pyramid_columns.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/compact.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace semimesh::ho {
namespace {

using mesh::NodeId;

// A piece of a split element: its shape and its vertices as reference points of the parent
// element (rows), in the piece's canonical vertex order, oriented like the parent.
struct Piece {
  Shape shape;
  Eigen::MatrixX3d corners;
};

// Reference point of every canonical node of `piece` in its parent: the affine map that takes the
// piece's reference vertices to `corners`. Shape (num_nodes(piece.shape, P), 3).
Eigen::MatrixX3d piece_nodes_in_parent(const Piece& piece, int order, NodeSet set) {
  const Eigen::MatrixX3d ref = reference_nodes(piece.shape, order, set);
  // The piece's own reference vertices are (0,0,0) (1,0,0) (0,1,0) and, for a prism, z in [-1, 1];
  // its first-order (P1) basis at its nodes times the corners is that affine map.
  const LagrangeBasis linear(piece.shape, 1, NodeSet::Equispaced);
  return linear.values(ref) * piece.corners;
}

// Orients a piece like its parent: a piece whose affine map from its reference element has a
// negative determinant gets its vertices 1 and 2 swapped (and 4 and 5 for a prism).
Piece oriented(Piece piece) {
  const Eigen::MatrixX3d ref = reference_vertices(piece.shape);
  const LagrangeBasis linear(piece.shape, 1, NodeSet::Equispaced);
  const std::vector<Eigen::Matrix3d> j = jacobians(linear, piece.corners, ref.topRows(1));
  if (j[0].determinant() < 0.0) {
    piece.corners.row(1).swap(piece.corners.row(2));
    if (piece.shape == Shape::Prism) piece.corners.row(4).swap(piece.corners.row(5));
  }
  return piece;
}

// The two prisms of the reference hexahedron [-1,1]^3 along `axis`, cut by diagonal 0 (the corners
// at (-1,-1) and (1,1) of the other two axes, in cyclic order) or 1 (the other two corners).
std::array<Piece, 2> hex_prisms(int axis, int diagonal) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  const std::array<Eigen::Vector2d, 4> square{Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1), Eigen::Vector2d(1, 1),
                                              Eigen::Vector2d(-1, 1)};
  const int s = diagonal;  // the triangles (s, s+1, s+2) and (s, s+2, s+3) around the square
  std::array<Piece, 2> out;
  for (int half = 0; half < 2; ++half) {
    const std::array<int, 3> t{s, (s + 1 + half) % 4, (s + 2 + half) % 4};
    Eigen::MatrixX3d corners(6, 3);
    for (int level = 0; level < 2; ++level)
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d p;
        p[axis] = level == 0 ? -1.0 : 1.0;
        p[b] = square[t[k]].x();
        p[c] = square[t[k]].y();
        corners.row(3 * level + k) = p.transpose();
      }
    out[half] = oriented({Shape::Prism, corners});
  }
  return out;
}

// The two tetrahedra of the reference pyramid on diagonal 0 (base vertices 0-2) or 1 (1-3).
std::array<Piece, 2> pyramid_tets(int diagonal) {
  const Eigen::MatrixX3d v = reference_vertices(Shape::Pyramid);
  const int s = diagonal;
  std::array<Piece, 2> out;
  for (int half = 0; half < 2; ++half) {
    Eigen::MatrixX3d corners(4, 3);
    corners.row(0) = v.row(s);
    corners.row(1) = v.row((s + 1 + half) % 4);
    corners.row(2) = v.row((s + 2 + half) % 4);
    corners.row(3) = v.row(4);
    out[half] = oriented({Shape::Tetrahedron, corners});
  }
  return out;
}

// For each node of a piece: the parent's canonical node at the same reference point, or -1 (a new
// node, placed by the parent's map).
std::vector<int> shared_parent_nodes(const Eigen::MatrixX3d& in_parent, const Eigen::MatrixX3d& parent_ref) {
  std::vector<int> out(in_parent.rows(), -1);
  for (Eigen::Index i = 0; i < in_parent.rows(); ++i)
    for (Eigen::Index j = 0; j < parent_ref.rows(); ++j)
      if ((parent_ref.row(j) - in_parent.row(i)).cwiseAbs().maxCoeff() < 1e-10) {
        out[i] = static_cast<int>(j);
        break;
      }
  return out;
}

// Element (or boundary quad) split instructions: which diagonal, and for hexes along which axis.
struct HexCut {
  int axis;
  int diagonal;
};

std::string element_label(const mesh::Mesh& m, std::size_t e) {
  const mesh::Element& el = m.elements()[e];
  const Eigen::Vector3d x = m.node(el.vertices[0]);
  std::ostringstream s;
  s << to_string(el.shape) << " " << e << " (region \"" << m.region_names()[el.region] << "\", vertex 0 at (" << x.x()
    << ", " << x.y() << ", " << x.z() << "))";
  return s.str();
}

// Reference axis and side (-1 or +1) of a hex's local face k.
std::pair<int, double> hex_face_axis(int k) {
  const Eigen::MatrixX3d v = reference_vertices(Shape::Hexahedron);
  const std::vector<int>& f = faces(Shape::Hexahedron)[k];
  for (int axis = 0; axis < 3; ++axis)
    if (v(f[0], axis) == v(f[1], axis) && v(f[0], axis) == v(f[2], axis)) return {axis, v(f[0], axis)};
  throw std::logic_error("hex_face_axis: face without a constant axis");
}

int local_face(const mesh::Element& el, std::uint32_t face) {
  const int n = static_cast<int>(faces(el.shape).size());
  for (int k = 0; k < n; ++k)
    if (el.faces[k] == face) return k;
  return -1;
}

int local_vertex(const mesh::Element& el, NodeId v) {
  for (int k = 0; k < num_vertices(el.shape); ++k)
    if (el.vertices[k] == v) return k;
  return -1;
}

class ColumnFinder {
 public:
  ColumnFinder(const mesh::Mesh& m, double tolerance) : m_(m), tolerance_(tolerance) {
    users_.assign(m.faces().size(), {kNone, kNone});
    for (std::size_t e = 0; e < m.elements().size(); ++e) {
      const mesh::Element& el = m.elements()[e];
      for (std::size_t k = 0; k < faces(el.shape).size(); ++k) {
        auto& u = users_[el.faces[k]];
        (u[0] == kNone ? u[0] : u[1]) = e;
      }
    }
    for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) boundary_of_face_[m.boundary_faces()[b].face] = b;
  }

  void run() {
    for (std::size_t e = 0; e < m_.elements().size(); ++e) {
      if (m_.elements()[e].shape != Shape::Pyramid || has_parallelogram_base(m_, e, tolerance_)) continue;
      ++stats.pyramids_refused;
      if (pyramid_cut.count(e)) continue;  // the far end of a column already split
      const mesh::Element& p = m_.elements()[e];
      const Eigen::Vector3d* x[4];
      for (int k = 0; k < 4; ++k) x[k] = &m_.node(p.vertices[k]);
      const bool short_02 = (*x[0] - *x[2]).squaredNorm() <= (*x[1] - *x[3]).squaredNorm();
      const std::array<NodeId, 2> diagonal = short_02 ? std::array<NodeId, 2>{p.vertices[0], p.vertices[2]}
                                                      : std::array<NodeId, 2>{p.vertices[1], p.vertices[3]};
      pyramid_cut[e] = short_02 ? 0 : 1;
      ++stats.columns;
      walk(e, p.faces[4], diagonal);
    }
    refuse_what_is_left();
  }

  std::map<std::size_t, HexCut> hex_cut;
  std::map<std::size_t, int> pyramid_cut;
  std::map<std::size_t, std::array<NodeId, 2>> boundary_cut;  // boundary face -> diagonal
  PyramidColumnStats stats;

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  // Every column walked first, so the message says how many are left of each kind, not only the first.
  void refuse_what_is_left() const {
    std::string why;
    if (dead_ends_ > 0)
      why = "the column of hexes under a pyramid whose base is not a parallelogram runs into " + first_dead_end_ +
            ": only hexes can be split into prisms along a column (" + std::to_string(dead_ends_) + " of the " +
            std::to_string(stats.pyramids_refused) + " refused pyramids' columns end so)";
    if (two_axes_ > 0)
      why += (why.empty() ? "" : "; ") + first_two_axes_ +
             " would have to be split into prisms along two axes (it carries pyramids whose bases are not "
             "parallelograms on two sides; " +
             std::to_string(two_axes_) + " such meeting(s))";
    if (!why.empty()) throw std::invalid_argument("split_pyramid_columns: " + why);
  }

  std::size_t across(std::uint32_t face, std::size_t from) const {
    const auto& u = users_[face];
    return u[0] == from ? u[1] : u[0];
  }

  // From element `from` through `face`, cut on the diagonal (global vertex ids), to the column's end.
  void walk(std::size_t from, std::uint32_t face, std::array<NodeId, 2> diagonal) {
    for (;;) {
      const std::size_t e = across(face, from);
      if (e == kNone) {
        const auto b = boundary_of_face_.find(face);
        if (b == boundary_of_face_.end())
          throw std::invalid_argument("split_pyramid_columns: a column from " + element_label(m_, from) +
                                      " ends on a face that is neither shared nor on the boundary");
        boundary_cut[b->second] = diagonal;
        ++stats.boundary_quads_split;
        return;
      }
      const mesh::Element& el = m_.elements()[e];
      if (el.shape == Shape::Pyramid) {
        pyramid_cut[e] = local_vertex(el, diagonal[0]) % 2;  // base vertices 0-2 or 1-3
        return;
      }
      if (el.shape != Shape::Hexahedron) {  // counted, the first named: the message says how many are left
        if (dead_ends_++ == 0) first_dead_end_ = element_label(m_, e);
        return;
      }
      const auto [axis, side] = hex_face_axis(local_face(el, face));
      const Eigen::MatrixX3d ref = reference_vertices(Shape::Hexahedron);
      const int a = local_vertex(el, diagonal[0]);
      const int b = (axis + 1) % 3, c = (axis + 2) % 3;
      const int cut = ref(a, b) == ref(a, c) ? 0 : 1;  // diagonal 0 joins (-1,-1) and (1,1)
      const auto [it, inserted] = hex_cut.insert({e, {axis, cut}});
      if (!inserted) {
        if (it->second.axis == axis && it->second.diagonal == cut) return;  // met the column from its other end
        if (two_axes_++ == 0) first_two_axes_ = element_label(m_, e);
        return;
      }
      ++stats.hexes_split;
      // The same diagonal on the opposite face: each end moved along the column axis.
      std::array<NodeId, 2> next{};
      for (int k = 0; k < 2; ++k) {
        Eigen::Vector3d p = ref.row(local_vertex(el, diagonal[k])).transpose();
        p[axis] = -side;
        for (int v = 0; v < 8; ++v)
          if ((ref.row(v).transpose() - p).cwiseAbs().maxCoeff() < 1e-12) next[k] = el.vertices[v];
      }
      int opposite = -1;
      for (int k = 0; k < 6; ++k)
        if (hex_face_axis(k) == std::pair<int, double>{axis, -side}) opposite = k;
      from = e;
      face = el.faces[opposite];
      diagonal = next;
    }
  }

  const mesh::Mesh& m_;
  double tolerance_;
  std::size_t dead_ends_ = 0;   ///< columns that ran into a prism or tetrahedron
  std::string first_dead_end_;  ///< the element the first one ran into
  std::size_t two_axes_ = 0;    ///< hexes two columns would split along different axes
  std::string first_two_axes_;
  std::vector<std::array<std::size_t, 2>> users_;
  std::map<std::uint32_t, std::size_t> boundary_of_face_;
};

// A piece as the split places it: its nodes' reference points in the parent, which of them are the
// parent's own nodes (-1: new), and the parent's basis at them. The same for every element cut the
// same way, so built once per cut.
struct PieceTable {
  Shape shape;
  std::vector<int> shared;
  Eigen::MatrixXd parent_values;  // (piece nodes, parent nodes)
};

std::vector<PieceTable> piece_tables(Shape parent, const std::array<Piece, 2>& pieces, int order, NodeSet set) {
  const LagrangeBasis basis(parent, order, set);
  std::vector<PieceTable> out;
  for (const Piece& piece : pieces) {
    const Eigen::MatrixX3d at = piece_nodes_in_parent(piece, order, set);
    out.push_back({piece.shape, shared_parent_nodes(at, basis.nodes()), basis.values(at)});
  }
  return out;
}

// Adds the pieces of element e to `out`: nodes the parent has at a piece's node are reused, the
// others are new nodes at the parent's map (a new node that another piece also has, on a cut face,
// is found equal by Mesh::add_element and the spare one dropped at the end).
void add_pieces(const mesh::Mesh& in, std::size_t e, const std::vector<PieceTable>& tables, mesh::Mesh& out) {
  const mesh::Element& el = in.elements()[e];
  const std::vector<NodeId> parent = in.element_nodes(e);
  const Eigen::MatrixX3d x = in.element_coordinates(e);
  for (const PieceTable& t : tables) {
    std::vector<NodeId> ids(t.shared.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
      ids[i] = t.shared[i] >= 0 ? parent[t.shared[i]]
                                : out.add_node((t.parent_values.row(static_cast<Eigen::Index>(i)) * x).transpose());
    out.add_element(t.shape, ids, el.region);
  }
}

// The two boundary triangles of boundary quad b cut on `diagonal`, in the quad's own orientation.
void add_boundary_triangles(const mesh::Mesh& in, std::size_t b, const std::array<NodeId, 2>& diagonal,
                            mesh::Mesh& out) {
  const mesh::BoundaryFace& f = in.boundary_faces()[b];
  const int P = in.order();
  const LagrangeBasis quad(Shape::Quadrilateral, P, in.node_set());
  const std::vector<NodeId> nodes = in.boundary_face_nodes(b);
  Eigen::MatrixX3d x(nodes.size(), 3);
  for (std::size_t i = 0; i < nodes.size(); ++i) x.row(i) = in.node(nodes[i]).transpose();
  const Eigen::MatrixX3d corners = reference_vertices(Shape::Quadrilateral);
  int s = 0;
  while (f.vertices[s] != diagonal[0] && f.vertices[s] != diagonal[1]) ++s;
  const Eigen::MatrixX3d tri_ref = reference_nodes(Shape::Triangle, P, in.node_set());
  const LagrangeBasis tri_linear(Shape::Triangle, 1, NodeSet::Equispaced);
  for (int half = 0; half < 2; ++half) {
    Eigen::MatrixX3d t(3, 3);
    t.row(0) = corners.row(s);
    t.row(1) = corners.row((s + 1 + half) % 4);
    t.row(2) = corners.row((s + 2 + half) % 4);
    const Eigen::MatrixX3d at = tri_linear.values(tri_ref) * t;
    const std::vector<int> shared = shared_parent_nodes(at, quad.nodes());
    const Eigen::MatrixX3d placed = map_points(quad, x, at);
    std::vector<NodeId> ids(at.rows());
    for (Eigen::Index i = 0; i < at.rows(); ++i)
      ids[i] = shared[i] >= 0 ? nodes[shared[i]] : out.add_node(placed.row(i).transpose());
    out.add_boundary_face(in.group_names()[f.group], Shape::Triangle, ids);
  }
}

}  // namespace

bool has_parallelogram_base(const mesh::Mesh& mesh, std::size_t pyramid, double tolerance) {
  const mesh::Element& p = mesh.elements()[pyramid];
  const auto x = [&](int k) { return mesh.node(p.vertices[k]); };
  return (x(0) - x(1) + x(2) - x(3)).cwiseAbs().maxCoeff() <= tolerance;
}

PyramidColumns split_pyramid_columns(mesh::Mesh in, double tolerance) {
  ColumnFinder columns(in, tolerance);
  columns.run();
  if (columns.stats.pyramids_refused == 0) return {std::move(in), columns.stats};
  columns.stats.pyramids_split = columns.pyramid_cut.size();

  mesh::Mesh out(in.order(), in.node_set());
  for (NodeId id = 0; id < in.num_nodes(); ++id) out.add_node(in.node(id), in.cad_attachment(id));
  for (const std::string& g : in.group_names()) out.group_index(g);
  out.copy_regions_from(in);
  out.reserve(Shape::Tetrahedron, in.elements().size() + columns.stats.hexes_split + columns.stats.pyramids_split);
  std::map<std::pair<int, int>, std::vector<PieceTable>> hex_tables;  // by (axis, diagonal)
  std::map<int, std::vector<PieceTable>> pyramid_tables;              // by diagonal
  const auto hex_table = [&](const HexCut& c) -> const std::vector<PieceTable>& {
    auto [it, fresh] = hex_tables.try_emplace({c.axis, c.diagonal});
    if (fresh) it->second = piece_tables(Shape::Hexahedron, hex_prisms(c.axis, c.diagonal), in.order(), in.node_set());
    return it->second;
  };
  const auto pyramid_table = [&](int diagonal) -> const std::vector<PieceTable>& {
    auto [it, fresh] = pyramid_tables.try_emplace(diagonal);
    if (fresh) it->second = piece_tables(Shape::Pyramid, pyramid_tets(diagonal), in.order(), in.node_set());
    return it->second;
  };
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < in.elements().size(); ++e) {
    if (const auto h = columns.hex_cut.find(e); h != columns.hex_cut.end())
      add_pieces(in, e, hex_table(h->second), out);
    else if (const auto p = columns.pyramid_cut.find(e); p != columns.pyramid_cut.end())
      add_pieces(in, e, pyramid_table(p->second), out);
    else {
      in.element_nodes(e, ids);
      out.add_element(in.elements()[e].shape, ids, in.elements()[e].region);
    }
  }
  for (std::size_t b = 0; b < in.boundary_faces().size(); ++b) {
    if (const auto c = columns.boundary_cut.find(b); c != columns.boundary_cut.end())
      add_boundary_triangles(in, b, c->second, out);
    else
      out.add_boundary_face(in.group_names()[in.boundary_faces()[b].group], in.boundary_faces()[b].shape,
                            in.boundary_face_nodes(b));
  }
  return {mesh::without_unreferenced_nodes(std::move(out)), columns.stats};
}

}  // namespace semimesh::ho
