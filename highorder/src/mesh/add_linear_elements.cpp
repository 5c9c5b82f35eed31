// Mesh::add_linear_elements: add_element of many linear elements, their edges found or added on
// this thread while another finds or adds their faces a block behind. The two lookups are
// separate tables and each pass meets its elements in order, so the ids are add_element's.
// The far field's ~320k tetrahedra were linked on one core while the other idled (~0.4 s).
#include "semimesh/mesh/mesh.hpp"

#include "entity_keys.hpp"

#include <atomic>
#include <exception>
#include <future>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace semimesh::mesh {
namespace {

// Elements the edge pass publishes at a time: the face pass stays a block behind, so the two
// threads rarely write the same elements' cache lines.
constexpr std::size_t kLinkBlock = 256;

}  // namespace

void Mesh::add_linear_elements(ho::Shape shape, const std::vector<NodeId>& vertices, int region) {
  if (order_ != 1)
    throw std::logic_error("Mesh::add_linear_elements: the mesh has order " + std::to_string(order_) +
                           " (linear elements only: use add_element)");
  if (ho::dimension(shape) != 3)
    throw std::invalid_argument("Mesh::add_linear_elements: " + ho::to_string(shape) + " is not a volume element");
  if (region < 0 || static_cast<std::size_t>(region) >= regions_.size())
    throw std::invalid_argument("Mesh::add_linear_elements: region " + std::to_string(region) + " does not exist (" +
                                std::to_string(regions_.size()) + " regions)");
  const auto nv = static_cast<std::size_t>(ho::num_vertices(shape));
  if (vertices.size() % nv != 0)
    throw std::invalid_argument("Mesh::add_linear_elements: " + std::to_string(vertices.size()) +
                                " vertex ids are not whole " + ho::to_string(shape) + "s of " + std::to_string(nv));
  const std::size_t count = vertices.size() / nv, first = elements_.size();
  // add_element's refusals, all before anything changes: a refused batch adds nothing.
  for (std::size_t k = 0; k < count; ++k) {
    const NodeId* v = vertices.data() + k * nv;
    const Named who{shape, first + k, nullptr};
    for (std::size_t a = 0; a < nv; ++a) {
      if (v[a] >= nodes_.size()) throw std::invalid_argument(who.text() + ": unknown node id " + std::to_string(v[a]));
      for (std::size_t b = a + 1; b < nv; ++b)
        if (v[a] == v[b]) throw std::invalid_argument(who.text() + ": vertex " + std::to_string(v[a]) + " appears twice");
    }
  }
  // What may still throw below is add_element's too: a quadrilateral face whose vertices an earlier
  // element gives in another cycle (twisted), and the lookups' id limit. The batch's elements are
  // then dropped; the entities linked so far stay, as a refused add_element leaves its own.
  Element blank;
  blank.shape = shape;
  blank.region = static_cast<std::uint16_t>(region);
  blank.first_node = static_cast<std::uint32_t>(interior_pool_.size());  // order 1: no interior nodes
  elements_.resize(first + count, blank);
  for (std::size_t k = 0; k < count; ++k) std::copy_n(vertices.data() + k * nv, nv, elements_[first + k].vertices.begin());

  const auto& local_edges = ho::edges(shape);
  const auto& local_faces = ho::faces(shape);
  const detail::FaceEdges& local_face_edges = detail::face_edges_of(shape);
  std::atomic<std::size_t> edges_done{0};
  const auto link_edges = [&] {
    for (std::size_t k = 0; k < count; ++k) {
      Element& el = elements_[first + k];
      std::array<std::uint64_t, 12> hashes;
      for (std::size_t e = 0; e < local_edges.size(); ++e) {
        hashes[e] = IdTable::mix(detail::edge_key(el.vertices[local_edges[e][0]], el.vertices[local_edges[e][1]]));
        edge_index_.prefetch(hashes[e]);
      }
      for (std::size_t e = 0; e < local_edges.size(); ++e) {
        const NodeId a = el.vertices[local_edges[e][0]], b = el.vertices[local_edges[e][1]];
        el.edges[e] = find_or_add_edge(a, b, hashes[e]);
        if (a > b) el.edge_reversed |= static_cast<std::uint16_t>(1u << e);
      }
      if ((k + 1) % kLinkBlock == 0) edges_done.store(k + 1, std::memory_order_release);
    }
    edges_done.store(count, std::memory_order_release);
  };
  std::atomic<bool> edges_failed{false};
  const auto link_faces = [&] {
    std::size_t ready = 0;
    for (std::size_t k = 0; k < count; ++k) {
      while (ready <= k) {
        ready = edges_done.load(std::memory_order_acquire);
        if (ready > k) break;
        if (edges_failed.load(std::memory_order_acquire)) return;
        std::this_thread::yield();
      }
      Element& el = elements_[first + k];
      const Named who{shape, first + k, nullptr};
      std::array<std::array<NodeId, 4>, 6> face_vertices{}, keys;
      for (std::size_t f = 0; f < local_faces.size(); ++f) {
        for (std::size_t i = 0; i < local_faces[f].size(); ++i) face_vertices[f][i] = el.vertices[local_faces[f][i]];
        keys[f] = detail::face_key(face_vertices[f].data(), static_cast<int>(local_faces[f].size()));
        face_index_.prefetch(detail::face_key_hash(keys[f]));
      }
      for (std::size_t f = 0; f < local_faces.size(); ++f) {
        std::array<std::uint32_t, 4> face_edges{};
        for (std::size_t i = 0; i < local_faces[f].size(); ++i) face_edges[i] = el.edges[local_face_edges[f][i]];
        el.faces[f] = find_or_add_face(face_vertices[f].data(), static_cast<int>(local_faces[f].size()), keys[f],
                                       face_edges.data(), el.face_orientation[f], who);
      }
    }
  };

  std::future<void> faces;
  try {
    faces = std::async(std::launch::async, link_faces);
  } catch (const std::system_error&) {  // no thread to be had: the passes one after the other
  }
  std::exception_ptr error;
  try {
    link_edges();
  } catch (...) {
    error = std::current_exception();
    edges_failed.store(true, std::memory_order_release);
  }
  try {
    if (faces.valid())
      faces.get();
    else if (!error)
      link_faces();
  } catch (...) {
    if (!error) error = std::current_exception();
  }
  if (error) {
    elements_.resize(first);
    std::rethrow_exception(error);
  }
}

}  // namespace semimesh::mesh
