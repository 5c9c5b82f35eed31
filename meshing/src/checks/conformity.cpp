#include "semimesh/checks/conformity.hpp"

#include "face_nodes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <future>
#include <thread>
#include <tuple>
#include <utility>

namespace semimesh::checks {
namespace {

using mesh::NodeId;

// One use of a face: by an element (its local face `local`) or by a boundary face.
struct Occurrence {
  std::array<NodeId, 4> key{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode, mesh::kNoNode};  // sorted vertices
  std::uint32_t owner = 0;         // element or boundary face index
  std::uint8_t local = 0;          // local face of the element
  bool boundary = false;
};

// Sorts the first n (3 or 4) entries: a plain insertion sort (std::sort on such short ranges trips
// GCC 12's -Warray-bounds).
void sort_key(std::array<NodeId, 4>& key, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && key[j] < key[j - 1]; --j) std::swap(key[j], key[j - 1]);
}

// use(o) for every use of a face by the items [first, end): the elements in order, then the
// boundary faces (item elements().size() + b).
template <class Use>
void uses_of(const mesh::Mesh& mesh, std::size_t first, std::size_t end, const Use& use) {
  const std::size_t num_elements = mesh.elements().size();
  for (std::size_t item = first; item < end; ++item) {
    if (item < num_elements) {
      const mesh::Element& element = mesh.elements()[item];
      const auto& faces = ho::faces(element.shape);
      for (std::size_t f = 0; f < faces.size(); ++f) {
        Occurrence o;
        for (std::size_t i = 0; i < faces[f].size(); ++i) o.key[i] = element.vertices[faces[f][i]];
        sort_key(o.key, static_cast<int>(faces[f].size()));
        o.owner = static_cast<std::uint32_t>(item);
        o.local = static_cast<std::uint8_t>(f);
        use(o);
      }
    } else {
      const std::size_t b = item - num_elements;
      const mesh::BoundaryFace& face = mesh.boundary_faces()[b];
      const int n = ho::num_vertices(face.shape);
      Occurrence o;
      std::copy(face.vertices.begin(), face.vertices.begin() + n, o.key.begin());
      sort_key(o.key, n);
      o.owner = static_cast<std::uint32_t>(b);
      o.boundary = true;
      use(o);
    }
  }
}

std::size_t num_items(const mesh::Mesh& mesh) { return mesh.elements().size() + mesh.boundary_faces().size(); }

std::vector<Occurrence> collect_occurrences(const mesh::Mesh& mesh) {
  std::vector<Occurrence> all;
  all.reserve(mesh.elements().size() * 5 + mesh.boundary_faces().size());
  uses_of(mesh, 0, num_items(mesh), [&](const Occurrence& o) { all.push_back(o); });
  return all;
}

int key_size(const std::array<NodeId, 4>& key) { return key[3] == mesh::kNoNode ? 3 : 4; }

// Vertex ids of an element's local face in the element's (outward) order, into `cycle` (a buffer
// of the caller's: this runs for both uses of every interior face).
void element_face_cycle(const mesh::Mesh& mesh, const Occurrence& o, std::vector<unsigned>& cycle) {
  const mesh::Element& element = mesh.elements()[o.owner];
  cycle.clear();
  for (int v : ho::faces(element.shape)[o.local]) cycle.push_back(element.vertices[v]);
}

// All node ids (vertices and high-order nodes) a user gives the face, sorted, into `nodes`. The
// buffers are reused (one set per thread): this runs for every use of every face.
void face_node_set(const mesh::Mesh& mesh, const Occurrence& o, std::vector<NodeId>& nodes) {
  if (o.boundary) {
    nodes = mesh.boundary_face_nodes(o.owner);
  } else {
    const mesh::Element& element = mesh.elements()[o.owner];
    mesh.element_nodes_at(o.owner, detail::nodes_on_faces(element.shape, mesh.order(), mesh.node_set())[o.local], nodes);
  }
  std::sort(nodes.begin(), nodes.end());
}

// The entities a use of a face reads its nodes from (face_sources): the face and its edges, sorted.
struct UseSources {
  std::uint32_t face = 0;
  std::array<std::uint32_t, 4> edges{};
  bool operator==(const UseSources& other) const { return face == other.face && edges == other.edges; }
};

// face_sources of a shape at the mesh's order and node set, remembered per thread by shape (the
// check asks for every use of every face; face_sources' own lookup is a map's).
const std::vector<detail::FaceSources>& sources_of(const mesh::Mesh& mesh, ho::Shape shape) {
  thread_local int order = 0;
  thread_local ho::NodeSet set = ho::NodeSet::Equispaced;
  thread_local std::array<const std::vector<detail::FaceSources>*, 16> known{};
  if (mesh.order() != order || mesh.node_set() != set) order = mesh.order(), set = mesh.node_set(), known.fill(nullptr);
  const auto slot = static_cast<std::size_t>(shape);
  if (slot >= known.size()) return detail::face_sources(shape, order, set);
  if (!known[slot]) known[slot] = &detail::face_sources(shape, order, set);
  return *known[slot];
}

// False when the layout reads more than those entities' whole runs (then the nodes are compared).
bool use_sources(const mesh::Mesh& mesh, const Occurrence& o, UseSources& out) {
  const auto sort_edges = [&](std::size_t n) { std::sort(out.edges.begin(), out.edges.begin() + static_cast<long>(n)); };
  out.edges.fill(0);
  if (o.boundary) {
    const mesh::BoundaryFace& face = mesh.boundary_faces()[o.owner];
    const detail::FaceSources& sources = sources_of(mesh, face.shape).front();
    if (!sources.whole) return false;
    out.face = face.face;
    for (std::size_t k = 0; k < sources.edges.size(); ++k) out.edges[k] = face.edges[sources.edges[k]];
    sort_edges(sources.edges.size());
    return true;
  }
  const mesh::Element& element = mesh.elements()[o.owner];
  const detail::FaceSources& sources = sources_of(mesh, element.shape)[o.local];
  if (!sources.whole) return false;
  out.face = element.faces[o.local];
  for (std::size_t k = 0; k < sources.edges.size(); ++k) out.edges[k] = element.edges[sources.edges[k]];
  sort_edges(sources.edges.size());
  return true;
}

// Whether classify may take uses that read the same entities as giving the same nodes (the fast
// check), or gathers and compares every use's nodes (the brute-force reference).
enum class Nodes { SameEntitiesSameNodes, CompareAll };

// Classifies the uses of one face; adds at most one problem per face (the most severe).
void classify(const mesh::Mesh& mesh, const std::vector<const Occurrence*>& uses, ConformityResult& result,
              Nodes nodes = Nodes::SameEntitiesSameNodes) {
  thread_local std::vector<const Occurrence*> elements, boundary;  // per face: no allocation each
  elements.clear(), boundary.clear();
  for (const Occurrence* o : uses) (o->boundary ? boundary : elements).push_back(o);

  auto report = [&](FaceProblem::Kind kind) {
    FaceProblem p;
    p.kind = kind;
    const auto& key = uses.front()->key;
    p.vertices.assign(key.begin(), key.begin() + key_size(key));
    for (const Occurrence* o : elements) p.elements.push_back(o->owner);
    for (const Occurrence* o : boundary) p.boundary_faces.push_back(o->owner);
    std::sort(p.elements.begin(), p.elements.end());
    std::sort(p.boundary_faces.begin(), p.boundary_faces.end());
    result.problems.push_back(std::move(p));
  };
  auto nodes_differ = [&]() {
    if (mesh.order() == 1) return false;  // the nodes are the vertices, equal by construction of the key
    // Uses that read the same entities' whole runs give the same set (their vertices are the key's):
    // no need to gather it. Uses naming other entities are compared node by node.
    thread_local UseSources first_sources, other_sources;
    if (nodes == Nodes::SameEntitiesSameNodes && use_sources(mesh, *uses.front(), first_sources) &&
        std::all_of(uses.begin() + 1, uses.end(), [&](const Occurrence* o) {
          return use_sources(mesh, *o, other_sources) && other_sources == first_sources;
        }))
      return false;
    thread_local std::vector<NodeId> first, other;
    face_node_set(mesh, *uses.front(), first);
    return std::any_of(uses.begin() + 1, uses.end(), [&](const Occurrence* o) {
      face_node_set(mesh, *o, other);
      return other != first;
    });
  };

  using Kind = FaceProblem::Kind;
  if (elements.size() > 2) return report(Kind::SharedByMoreThanTwo);
  if (elements.empty()) return report(Kind::BoundaryWithoutElement);
  if (nodes_differ()) return report(Kind::DifferentNodes);
  if (elements.size() == 2) {
    thread_local std::vector<unsigned> one, other;
    element_face_cycle(mesh, *elements[0], one);
    element_face_cycle(mesh, *elements[1], other);
    if (detail::same_cycle(one, other)) return report(Kind::SameSide);
    if (!boundary.empty()) return report(Kind::BoundaryOnInteriorFace);
    ++result.interior_faces;
    return;
  }
  if (boundary.empty()) return report(Kind::Unmatched);
  if (boundary.size() > 1) return report(Kind::BoundaryRepeated);
  ++result.boundary_faces;
}

void sort_problems(ConformityResult& result) {
  std::sort(result.problems.begin(), result.problems.end(),
            [](const FaceProblem& a, const FaceProblem& b) { return std::tie(a.kind, a.vertices) < std::tie(b.kind, b.vertices); });
}

}  // namespace

std::string to_string(FaceProblem::Kind kind) {
  switch (kind) {
    case FaceProblem::Kind::SharedByMoreThanTwo: return "face shared by more than two elements";
    case FaceProblem::Kind::SameSide: return "two elements on the same side of a face (overlap)";
    case FaceProblem::Kind::DifferentNodes: return "users of a face give it different nodes";
    case FaceProblem::Kind::Unmatched: return "face of one element that is not on the boundary (gap or hole)";
    case FaceProblem::Kind::BoundaryOnInteriorFace: return "boundary face between two elements";
    case FaceProblem::Kind::BoundaryRepeated: return "face is a boundary face more than once";
    case FaceProblem::Kind::BoundaryWithoutElement: return "boundary face of no element";
  }
  return "unknown";
}

std::string FaceProblem::describe(const mesh::Mesh& mesh) const {
  std::string text = fmt::format("{} at ({:.6g}, {:.6g}, {:.6g}), vertices [{}]", to_string(kind), centroid.x(),
                                 centroid.y(), centroid.z(), fmt::join(vertices, " "));
  if (!elements.empty()) text += fmt::format(", elements [{}]", fmt::join(elements, " "));
  for (std::size_t b : boundary_faces)
    text += fmt::format(", boundary face {} ({})", b, mesh.group_names()[mesh.boundary_faces()[b].group]);
  return text;
}

namespace {

// (key, boundary, owner, local) in lexicographic order, as three 64-bit words: the sort's
// comparisons, millions of them, no longer walk the key's array id by id.
bool occurs_before(const Occurrence& a, const Occurrence& b) {
  const auto word = [](NodeId high, NodeId low) { return (static_cast<std::uint64_t>(high) << 32) | low; };
  const auto use = [](const Occurrence& o) {
    return (static_cast<std::uint64_t>(o.boundary) << 40) | (static_cast<std::uint64_t>(o.owner) << 8) | o.local;
  };
  const std::uint64_t a0 = word(a.key[0], a.key[1]), b0 = word(b.key[0], b.key[1]);
  if (a0 != b0) return a0 < b0;
  const std::uint64_t a1 = word(a.key[2], a.key[3]), b1 = word(b.key[2], b.key[3]);
  if (a1 != b1) return a1 < b1;
  return use(a) < use(b);
}

// Runs part(k) for k in [0, parts) on threads of their own, part 0 on this one.
template <class Part>
void run_parts(std::size_t parts, const Part& part) {
  std::vector<std::future<void>> others;
  for (std::size_t k = 1; k < parts; ++k) others.push_back(std::async(std::launch::async, part, k));
  std::exception_ptr error;
  try {
    part(0);
  } catch (...) {
    error = std::current_exception();
  }
  for (auto& other : others) other.wait();
  if (error) std::rethrow_exception(error);
  for (auto& other : others) other.get();
}

// Every use of a face, sorted by occurs_before, without comparing most pairs: a counting pass
// finds how many uses fall in each bucket of smallest vertices (a few faces a bucket), a second
// pass writes each use into its bucket's room, then each bucket is sorted on its own. Buckets
// follow each other in key order, so the whole is sorted: a face's uses are next to each other (the
// brute force check, which groups them without sorting, is the tests' reference). Both passes over
// the elements and the buckets' sorts are shared among `parts` threads; the order is
// occurs_before's alone, whatever the parts.
std::vector<Occurrence> sorted_occurrences(const mesh::Mesh& mesh, std::size_t parts) {
  const std::size_t num_nodes = mesh.num_nodes(), items = num_items(mesh);
  const std::size_t at_most = 6 * mesh.elements().size() + mesh.boundary_faces().size();
  int shift = 0;  // buckets of 2^shift smallest vertices: about one bucket per 8 uses
  while ((num_nodes >> shift) > std::max<std::size_t>(1, at_most / 8)) ++shift;
  const std::size_t buckets = (num_nodes >> shift) + 1;
  const auto bucket = [shift](const Occurrence& o) { return static_cast<std::size_t>(o.key[0]) >> shift; };
  std::vector<std::size_t> bounds;
  for (std::size_t k = 0; k <= parts; ++k) bounds.push_back(items * k / parts);
  // starts[k][b]: where part k's first use in bucket b goes (parts in order within a bucket).
  std::vector<std::vector<std::size_t>> starts(parts, std::vector<std::size_t>(buckets + 1, 0));
  run_parts(parts, [&](std::size_t k) {
    uses_of(mesh, bounds[k], bounds[k + 1], [&](const Occurrence& o) { ++starts[k][bucket(o)]; });
  });
  std::size_t at = 0;
  std::vector<std::size_t> bucket_start(buckets + 1);
  for (std::size_t b = 0; b < buckets; ++b) {
    bucket_start[b] = at;
    for (std::size_t k = 0; k < parts; ++k) at += std::exchange(starts[k][b], at);
  }
  bucket_start[buckets] = at;
  std::vector<Occurrence> sorted(at);
  run_parts(parts, [&](std::size_t k) {
    uses_of(mesh, bounds[k], bounds[k + 1], [&](const Occurrence& o) { sorted[starts[k][bucket(o)]++] = o; });
  });
  starts = {};
  run_parts(parts, [&](std::size_t k) {
    for (std::size_t b = buckets * k / parts; b < buckets * (k + 1) / parts; ++b)
      std::sort(sorted.begin() + static_cast<long>(bucket_start[b]),
                sorted.begin() + static_cast<long>(bucket_start[b + 1]), occurs_before);
  });
  return sorted;
}

// The faces of sorted occurrences [first, end) classified into `result`.
void classify_range(const mesh::Mesh& mesh, const std::vector<Occurrence>& all, std::size_t first, std::size_t end,
                    ConformityResult& result) {
  std::vector<const Occurrence*> uses;
  for (std::size_t i = first; i < end;) {
    std::size_t j = i;
    uses.clear();
    for (; j < end && all[j].key == all[i].key; ++j) uses.push_back(&all[j]);
    classify(mesh, uses, result);
    i = j;
  }
}

// Where the sorted occurrences split into about equal parts without splitting a face's uses.
std::vector<std::size_t> face_aligned_bounds(const std::vector<Occurrence>& all, std::size_t parts) {
  std::vector<std::size_t> bounds{0};
  for (std::size_t k = 1; k < parts; ++k) {
    std::size_t at = std::max(bounds.back(), all.size() * k / parts);
    while (at > 0 && at < all.size() && all[at].key == all[at - 1].key) ++at;
    bounds.push_back(at);
  }
  bounds.push_back(all.size());
  return bounds;
}

}  // namespace

ConformityResult check_conformity(const mesh::Mesh& mesh, Located located) {
  // The serial passes' longest: its sort and its faces on all cores (the counts and the sorted
  // problems do not depend on how the faces are shared out).
  const std::size_t parts = std::max(1u, std::thread::hardware_concurrency());
  const std::vector<Occurrence> all = sorted_occurrences(mesh, parts);
  const std::vector<std::size_t> bounds = face_aligned_bounds(all, parts);
  std::vector<ConformityResult> part_results(parts);
  run_parts(parts, [&](std::size_t k) { classify_range(mesh, all, bounds[k], bounds[k + 1], part_results[k]); });
  ConformityResult result;
  for (ConformityResult& part : part_results) {
    result.interior_faces += part.interior_faces;
    result.boundary_faces += part.boundary_faces;
    for (FaceProblem& p : part.problems) result.problems.push_back(std::move(p));
  }
  sort_problems(result);
  if (located == Located::Yes) locate_problems(mesh, result);
  return result;
}

void locate_problems(const mesh::Mesh& mesh, ConformityResult& result) {
  for (FaceProblem& p : result.problems) {
    p.centroid.setZero();
    for (NodeId v : p.vertices) p.centroid += mesh.node(v);
    p.centroid /= static_cast<double>(p.vertices.size());
  }
}

ConformityResult check_conformity_brute_force(const mesh::Mesh& mesh) {
  const std::vector<Occurrence> all = collect_occurrences(mesh);
  std::vector<bool> grouped(all.size(), false);
  ConformityResult result;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (grouped[i]) continue;
    std::vector<const Occurrence*> uses{&all[i]};
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (grouped[j] || key_size(all[j].key) != key_size(all[i].key)) continue;
      // Same face when every vertex of one is a vertex of the other (no sorting involved).
      const int n = key_size(all[i].key);
      bool same = true;
      for (int a = 0; a < n && same; ++a)
        same = std::find(all[j].key.begin(), all[j].key.begin() + n, all[i].key[a]) != all[j].key.begin() + n;
      if (same) {
        grouped[j] = true;
        uses.push_back(&all[j]);
      }
    }
    classify(mesh, uses, result, Nodes::CompareAll);
  }
  sort_problems(result);
  locate_problems(mesh, result);
  return result;
}

}  // namespace semimesh::checks
