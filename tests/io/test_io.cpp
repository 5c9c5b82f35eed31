// Writers and readers: atomic output (files, and the .vtm's folder of pieces), MSH round trips,
// reader error locations, VTK permutations, GLL -> equispaced resampling, writers' progress.
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/output_set.hpp"
#include "semimesh/io/vtk_order.hpp"
#include "semimesh/io/vtu.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <dirent.h>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/stat.h>
#include <utility>
#include <vector>
#include <unistd.h>

namespace {

using semimesh::ho::NodeSet;
using semimesh::ho::Shape;
using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;

// A fresh directory under /tmp, removed when the test program exits.
std::string temp_dir() {
  struct Cleanup {
    std::vector<std::string> dirs;
    ~Cleanup() {
      for (const auto& d : dirs) std::filesystem::remove_all(d);
    }
  };
  static Cleanup cleanup;
  char name[] = "/tmp/semimesh_test_io_XXXXXX";
  const char* d = ::mkdtemp(name);
  if (!d) throw std::runtime_error("mkdtemp failed");
  cleanup.dirs.push_back(d);
  return d;
}

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d))
      if (e->d_name[0] != '.') names.push_back(e->d_name);
    ::closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A polynomial map of degree 2 (reproduced exactly by every element of order >= 2).
Eigen::Vector3d quadratic_map(const Eigen::Vector3d& r) {
  return {r[0] + 0.1 * r[1] * r[1], r[1] + 0.05 * r[0] * r[2], r[2] - 0.08 * r[0] * r[0] + 0.3};
}

// Two prisms of order P split from the hex [0,1]^3 along the diagonal (1,0)-(0,1), with nodes on
// a shared (P+1)^3 lattice bent by quadratic_map, and their 8 boundary faces in two groups.
Mesh two_prisms(int p, NodeSet set = NodeSet::Equispaced) {
  Mesh mesh(p, set);
  const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Prism, p, set);
  std::map<std::array<long, 3>, NodeId> lattice;
  auto node_at = [&](const Eigen::Vector3d& x) {
    const std::array<long, 3> key = {std::lround(x[0] * 1e9), std::lround(x[1] * 1e9), std::lround(x[2] * 1e9)};
    auto it = lattice.find(key);
    if (it == lattice.end()) it = lattice.emplace(key, mesh.add_node(quadratic_map(x))).first;
    return it->second;
  };
  for (int half = 0; half < 2; ++half) {
    std::vector<NodeId> ids;
    for (int i = 0; i < ref.rows(); ++i) {
      // Prism A: (u, v) -> (u, v); prism B: (u, v) -> (1 - u, 1 - v) (180 degree turn).
      const double u = ref(i, 0), v = ref(i, 1), w = 0.5 * (ref(i, 2) + 1);
      ids.push_back(node_at(half == 0 ? Eigen::Vector3d(u, v, w) : Eigen::Vector3d(1 - u, 1 - v, w)));
    }
    mesh.add_element(Shape::Prism, ids);
  }
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const auto& face = mesh.faces()[f];
    // Skip the shared diagonal face: its vertices have x + y = 1.
    bool diagonal = true;
    for (int k = 0; k < face.num_vertices; ++k) {
      const auto& x = mesh.node(face.vertices[k]);
      diagonal = diagonal && std::abs(x[0] + x[1] - 1.0) < 0.2;
    }
    if (diagonal) continue;
    const bool tri = face.num_vertices == 3;
    mesh.add_boundary_face(tri ? "wall" : "side", tri ? Shape::Triangle : Shape::Quadrilateral, mesh.face_nodes(f));
  }
  return mesh;
}

TEST(AtomicFile, FailureLeavesTheOldFileAndNoTemporary) {
  const std::string dir = temp_dir();
  const std::string path = dir + "/mesh.msh";
  { std::ofstream(path) << "old content\n"; }
  try {
    semimesh::io::AtomicFile out(path);
    out.print("new {}\n", 1);
    throw std::runtime_error("writer failed half way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_text(path), "old content\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"mesh.msh"});
  {
    semimesh::io::AtomicFile out(path);
    out.print("new {}\n", 2);
    out.commit();
  }
  EXPECT_EQ(read_text(path), "new 2\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"mesh.msh"});
  try {
    semimesh::io::AtomicFile out("/nonexistent_dir_for_semimesh/mesh.msh");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_dir_for_semimesh"), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, CommittedFileHasTheUsualPermissions) {
  const std::string path = temp_dir() + "/mesh.msh";
  const mode_t mask = ::umask(022);
  {
    semimesh::io::AtomicFile out(path);
    out.print("x\n");
    out.commit();
  }
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

// Pieces of a MB or more go to the file without the buffer: the bytes still land in the order
// written, and a placeholder is still filled in wherever it went.
TEST(AtomicFile, LargePiecesGoInOrderAndPlaceholdersAreFilledIn) {
  const std::string path = temp_dir() + "/large.bin";
  const std::string large(std::size_t{3} << 20, 'L');
  std::string want = "head" + large + "tail" + large;
  {
    semimesh::io::AtomicFile out(path);
    out.write("head");
    out.write(large.data(), large.size());
    out.write("tail");
    out.write(large.data(), large.size());
    out.overwrite(1, "E", 1);                // before the first large piece, already in the file
    out.overwrite(10, "XY", 2);              // inside it
    out.overwrite(want.size() - 1, "Z", 1);  // the last byte
    out.commit();
  }
  want[1] = 'E', want[10] = 'X', want[11] = 'Y', want.back() = 'Z';
  EXPECT_EQ(read_text(path), want);
}

// Text and binary pieces of every size across many buffers (each written by the file's own thread
// while the next is filled) land in the order they were given.
TEST(AtomicFile, ManyBuffersLandInOrder) {
  const std::string path = temp_dir() + "/many.bin";
  std::string want;
  {
    semimesh::io::AtomicFile out(path);
    for (int i = 0; i < 400000; ++i) {
      out.print("{} ", i);
      want += std::to_string(i) + " ";
      if (i % 50000 == 7) {
        const std::string piece(std::size_t(i % 3 + 1) << 19, static_cast<char>('a' + i % 26));
        out.write(piece.data(), piece.size());
        want += piece;
      }
    }
    EXPECT_EQ(out.bytes_written(), want.size());
    out.commit();
  }
  EXPECT_EQ(read_text(path), want);
}

// A write that fails on the file's own thread (here at the process's file size limit: EFBIG) is
// thrown to the caller by a later write or by commit, naming the file; the old file stays.
TEST(AtomicFile, AFailedBackgroundWriteIsThrownAndTheOldFileStays) {
  const std::string dir = temp_dir();
  const std::string path = dir + "/big.msh";
  { std::ofstream(path) << "old\n"; }
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of the signal
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit limit = old_limit;
  limit.rlim_cur = rlim_t{2} << 20;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::string error;
  try {
    semimesh::io::AtomicFile out(path);
    const std::string piece(std::size_t{1} << 20, 'x');
    for (int i = 0; i < 8; ++i) out.write(piece.data(), piece.size());
    out.commit();
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(error.find("cannot write to '" + dir + "/big.msh.tmp-"), std::string::npos) << error;
  EXPECT_EQ(read_text(path), "old\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"big.msh"});
}

TEST(Msh, WriteFailureKeepsExistingFile) {
  const std::string dir = temp_dir();
  const std::string path = dir + "/m.msh";
  { std::ofstream(path) << "keep\n"; }
  Mesh too_high(10);  // MSH tables stop at order 9 (Gmsh has no order-10 prism, pyramid or hex)
  EXPECT_THROW(semimesh::io::write_msh(too_high, path), std::invalid_argument);
  EXPECT_EQ(read_text(path), "keep\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"m.msh"});
}

// Every entry of a folder, hidden ones too (a staging folder left behind would show here).
std::vector<std::string> all_entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputSet, CommitReplacesOlderFilesAndFoldersTogether) {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/a.msh") << "older a\n"; }
  std::filesystem::create_directories(dir + "/pieces/stale");
  { std::ofstream(dir + "/other.txt") << "not ours\n"; }
  {
    semimesh::io::OutputSet set(dir);
    { std::ofstream(set.staged("a.msh")) << "new a\n"; }
    { std::ofstream(set.staged("b.json")) << "new b\n"; }
    std::filesystem::create_directories(set.staged("pieces") + "/fresh");
    EXPECT_EQ(read_text(dir + "/a.msh"), "older a\n") << "nothing moves before commit";
    EXPECT_EQ(set.final_path(set.staged("b.json")), dir + "/b.json");
    set.commit();
  }
  EXPECT_EQ(all_entries(dir), (std::vector<std::string>{"a.msh", "b.json", "other.txt", "pieces"}));
  EXPECT_EQ(read_text(dir + "/a.msh"), "new a\n");
  EXPECT_EQ(all_entries(dir + "/pieces"), std::vector<std::string>{"fresh"}) << "replaced, not merged";
}

TEST(OutputSet, WithoutCommitTheFolderStaysAsItWas) {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/a.msh") << "older a\n"; }
  {
    semimesh::io::OutputSet set(dir);
    { std::ofstream(set.staged("a.msh")) << "new a\n"; }
    { std::ofstream(set.staged("b.json")) << "new b\n"; }
  }
  EXPECT_EQ(all_entries(dir), std::vector<std::string>{"a.msh"});
  EXPECT_EQ(read_text(dir + "/a.msh"), "older a\n");
}

TEST(OutputSet, AFolderInTheWayOfAFileIsRefusedBeforeAnythingMoves) {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/a.msh") << "older a\n"; }
  std::filesystem::create_directories(dir + "/b.vtu/inside");
  semimesh::io::OutputSet set(dir);
  { std::ofstream(set.staged("a.msh")) << "new a\n"; }
  { std::ofstream(set.staged("b.vtu")) << "new b\n"; }
  try {
    set.commit();
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/b.vtu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("folder"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text(dir + "/a.msh"), "older a\n");
  EXPECT_TRUE(std::filesystem::exists(dir + "/b.vtu/inside"));
  EXPECT_THROW(set.staged("sub/a.msh"), std::invalid_argument);
}

TEST(Vtm, ReplacesAnOlderFolderWholeWithTheUsualPermissions) {
  const std::string dir = temp_dir();
  const std::string path = dir + "/m.vtm";
  semimesh::io::write_vtm(two_prisms(2), path);
  const std::vector<std::string> pieces = {"boundary0_wall.vtu", "boundary1_side.vtu", "volume.vtu"};
  EXPECT_EQ(list_dir(dir + "/m"), pieces);
  { std::ofstream(dir + "/m/stale.vtu") << "from an older run\n"; }
  const mode_t mask = ::umask(022);
  semimesh::io::write_vtm(two_prisms(3), path);
  ::umask(mask);
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"m", "m.vtm"}));
  EXPECT_EQ(list_dir(dir + "/m"), pieces) << "the older folder is replaced, not merged";
  EXPECT_NE(read_text(path).find("name=\"volume\" file=\"m/volume.vtu\""), std::string::npos) << read_text(path);
  struct stat info {};
  ASSERT_EQ(::stat((dir + "/m").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0755u);
}

TEST(Vtm, FailureHalfWayLeavesTheOlderPairAndNoTemporary) {
  const std::string dir = temp_dir();
  const std::string path = dir + "/m.vtm";
  semimesh::io::write_vtm(two_prisms(2), path);
  const std::string index = read_text(path), volume = read_text(dir + "/m/volume.vtu");
  // A progress callback that throws stands for any failure after some pieces are written.
  int calls = 0;
  const semimesh::ProgressCallback fail_late = [&](double, const std::string&) {
    if (++calls == 10) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(semimesh::io::write_vtm(two_prisms(3), path, fail_late), std::runtime_error);
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"m", "m.vtm"}));
  EXPECT_EQ(read_text(path), index);
  EXPECT_EQ(read_text(dir + "/m/volume.vtu"), volume);
  EXPECT_GE(calls, 10) << "the failure must come after a piece was written";
}

TEST(Msh, ProgressRisesToOneFromTheWritingThread) {
  std::vector<double> fractions;
  const semimesh::ProgressCallback record = [&](double f, const std::string&) { fractions.push_back(f); };
  semimesh::io::write_msh(two_prisms(3), temp_dir() + "/m.msh", semimesh::io::MshVersion::V41,
                          semimesh::io::MshEncoding::Ascii, record);
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

// (order, version, encoding): MSH 4.1 ASCII and binary (the default `msh41`), 2.2 ASCII.
class MshRoundTrip
    : public ::testing::TestWithParam<std::tuple<int, semimesh::io::MshVersion, semimesh::io::MshEncoding>> {};

TEST_P(MshRoundTrip, ReadBackGivesTheSameMesh) {
  const auto [p, version, encoding] = GetParam();
  const Mesh mesh = two_prisms(p);
  const std::string path = temp_dir() + "/two_prisms.msh";
  semimesh::io::write_msh(mesh, path, version, encoding);
  const Mesh back = semimesh::io::read_msh(path);
  EXPECT_EQ(back.order(), p);
  ASSERT_EQ(back.elements().size(), 2u);
  EXPECT_EQ(back.num_nodes(), static_cast<std::size_t>((p + 1) * (p + 1) * (p + 1)));
  EXPECT_EQ(back.edges().size(), 14u);  // 9 + 9 - 4 on the shared quad
  EXPECT_EQ(back.faces().size(), 9u);
  for (std::size_t e = 0; e < 2; ++e)
    EXPECT_LT((back.element_coordinates(e) - mesh.element_coordinates(e)).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(back.boundary_faces().size(), 8u);
  std::vector<std::string> groups = back.group_names();
  std::sort(groups.begin(), groups.end());
  EXPECT_EQ(groups, (std::vector<std::string>{"side", "wall"}));
  // MSH 4.1 groups boundary faces by (group, type), so match them through their face entity; the
  // reader keeps node ids (file order = NodeId order).
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    const auto& bf = mesh.boundary_faces()[b];
    const long face = back.find_face(std::vector<NodeId>(bf.vertices.begin(),
                                                         bf.vertices.begin() + semimesh::ho::num_vertices(bf.shape)));
    ASSERT_GE(face, 0);
    std::size_t match = 0;
    while (match < back.boundary_faces().size() && back.boundary_faces()[match].face != static_cast<std::uint32_t>(face))
      ++match;
    ASSERT_LT(match, back.boundary_faces().size());
    EXPECT_EQ(back.boundary_face_nodes(match), mesh.boundary_face_nodes(b));
    EXPECT_EQ(back.group_names()[back.boundary_faces()[match].group], mesh.group_names()[bf.group]);
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, MshRoundTrip,
                         ::testing::Combine(::testing::Values(1, 2, 3, 4, 6, 8, 9),
                                            ::testing::Values(semimesh::io::MshVersion::V41,
                                                              semimesh::io::MshVersion::V22),
                                            ::testing::Values(semimesh::io::MshEncoding::Ascii)));
INSTANTIATE_TEST_SUITE_P(Binary, MshRoundTrip,
                         ::testing::Combine(::testing::Values(1, 2, 3, 4, 6, 8, 9),
                                            ::testing::Values(semimesh::io::MshVersion::V41),
                                            ::testing::Values(semimesh::io::MshEncoding::Binary)));

// The binary file reads back bit for bit as the ASCII one (the writer prints shortest round-trip
// decimals, so both hold the same doubles).
TEST(Msh, BinaryAndAsciiReadBackAlike) {
  const Mesh mesh = two_prisms(4);
  const std::string ascii = temp_dir() + "/alike_ascii.msh", binary = temp_dir() + "/alike_binary.msh";
  semimesh::io::write_msh(mesh, ascii, semimesh::io::MshVersion::V41, semimesh::io::MshEncoding::Ascii);
  semimesh::io::write_msh(mesh, binary, semimesh::io::MshVersion::V41, semimesh::io::MshEncoding::Binary);
  const Mesh a = semimesh::io::read_msh(ascii), b = semimesh::io::read_msh(binary);
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  for (NodeId id = 0; id < a.num_nodes(); ++id) EXPECT_EQ(a.node(id), b.node(id));
  ASSERT_EQ(a.elements().size(), b.elements().size());
  for (std::size_t e = 0; e < a.elements().size(); ++e) EXPECT_EQ(a.element_nodes(e), b.element_nodes(e));
  ASSERT_EQ(a.boundary_faces().size(), b.boundary_faces().size());
  for (std::size_t f = 0; f < a.boundary_faces().size(); ++f) {
    EXPECT_EQ(a.boundary_face_nodes(f), b.boundary_face_nodes(f));
    EXPECT_EQ(a.group_names()[a.boundary_faces()[f].group], b.group_names()[b.boundary_faces()[f].group]);
  }
}

// Two tets, of regions "wing_layer" and `far_region`, and one boundary triangle of group "farfield".
Mesh two_regions_beside_a_group(const std::string& far_region) {
  Mesh mesh(1);
  std::vector<NodeId> ids;
  for (const auto& x : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                        Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 1, 1)})
    ids.push_back(mesh.add_node(x));
  mesh.add_element(Shape::Tetrahedron, {ids[0], ids[1], ids[2], ids[3]}, mesh.region_index("wing_layer"));
  mesh.add_element(Shape::Tetrahedron, {ids[1], ids[2], ids[3], ids[4]}, mesh.region_index(far_region));
  mesh.add_boundary_face("farfield", Shape::Triangle, {ids[0], ids[2], ids[1]});
  return mesh;
}

TEST(Msh, PhysicalTagsAreUniqueAcrossDimensionsAndOneVolumePerRegion) {
  const Mesh mesh = two_regions_beside_a_group("farfield");
  const std::string path = temp_dir() + "/regions.msh";
  semimesh::io::write_msh(mesh, path);
  const std::string text = read_text(path);
  // Region 0 ("fluid") has no element: no group. The region named like the boundary group is renamed.
  EXPECT_NE(text.find("$PhysicalNames\n3\n2 1 \"farfield\"\n3 2 \"wing_layer\"\n3 3 \"farfield_volume\"\n"),
            std::string::npos)
      << text.substr(0, 200);
}

// The region named like the boundary group is "farfield_volume" in the XML's composites as in the
// MSH's physical names: the file's reader sees one "farfield", the boundary.
TEST(Nektar, CompositesOfARegionNamedLikeABoundaryGroupTakeTheVolumeName) {
  const Mesh mesh = two_regions_beside_a_group("FarField");  // the same name but for case
  const std::string path = temp_dir() + "/regions.xml";
  semimesh::io::write_nektar_xml(mesh, path, semimesh::io::NektarEncoding::Plain);
  const std::string text = read_text(path);
  EXPECT_NE(text.find("NAME=\"wing_layer\"> A[0]"), std::string::npos) << text;
  EXPECT_NE(text.find("NAME=\"FarField_volume\"> A[1]"), std::string::npos) << text;
  EXPECT_NE(text.find("NAME=\"farfield\"> F["), std::string::npos) << text;
  EXPECT_EQ(text.find("NAME=\"FarField\""), std::string::npos) << text;
}

TEST(Nektar, TwoPyramidsSharingATriangleThrowNamingTheElement) {
  // Pyramid A's triangle (a, b, apex_A) is pyramid B's triangle with apex a: each apex would have
  // to be the highest vertex of the shared triangle.
  Mesh mesh(1);
  auto node = [&](double x, double y, double z) { return mesh.add_node(Eigen::Vector3d(x, y, z)); };
  const NodeId a = node(1, 0, 0), b = node(1, 1, 0), c = node(0.5, 0.5, 1);
  mesh.add_element(Shape::Pyramid, {node(0, 0, 0), a, b, node(0, 1, 0), c});
  mesh.add_element(Shape::Pyramid, {b, c, node(1.5, 1.5, 1.5), node(1.6, 1.4, 0.2), a});
  try {
    semimesh::io::write_nektar_xml(mesh, temp_dir() + "/pyramids.xml");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("element "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("pyramid"), std::string::npos) << e.what();
  }
}

TEST(Msh, ReaderErrorsGiveFileAndLine) {
  const std::string path = temp_dir() + "/bad.msh";
  {
    std::ofstream out(path);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n3 1 0 2\n1\n2\n0 0 0\n0 0\n$EndNodes\n";
  }
  try {
    semimesh::io::read_msh(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":10:"), std::string::npos) << e.what();
  }
  {
    // Binary data cut short in $Nodes: the error names the section's line.
    std::ofstream out(path, std::ios::binary);
    const int one = 1;
    const std::size_t head[2] = {1, 2};
    out << "$MeshFormat\n4.1 1 8\n";
    out.write(reinterpret_cast<const char*>(&one), sizeof one);
    out << "\n$EndMeshFormat\n$Nodes\n";
    out.write(reinterpret_cast<const char*>(head), sizeof head);
  }
  try {
    semimesh::io::read_msh(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":5: unexpected end of file in binary data"), std::string::npos)
        << e.what();
  }
  {
    std::ofstream out(path);
    out << "$MeshFormat\n4.1 1 8\nABCD\n$EndMeshFormat\n";  // not the little-endian 1
  }
  try {
    semimesh::io::read_msh(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("big-endian"), std::string::npos) << e.what();
  }
  EXPECT_THROW(semimesh::io::read_msh(path + ".missing"), std::runtime_error);
}

TEST(VtkOrder, IsAPermutationWithVerticesFirst) {
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Prism, Shape::Hexahedron})
    for (int p = 1; p <= 6; ++p) {
      std::vector<int> perm = semimesh::io::vtk_from_canonical(shape, p);
      ASSERT_EQ(static_cast<int>(perm.size()), semimesh::ho::num_nodes(shape, p));
      for (int k = 0; k < semimesh::ho::num_vertices(shape); ++k) EXPECT_EQ(perm[k], k);
      std::sort(perm.begin(), perm.end());
      for (std::size_t i = 0; i < perm.size(); ++i) ASSERT_EQ(perm[i], static_cast<int>(i));
    }
  // VTK 9.1 hexahedron (file version 2.2): the 27-node hex's 11th edge node is on edge 2-6
  // (x = y = 1), its 12th on edge 3-7 (vtkHigherOrderHexahedron::PointIndexFromIJK).
  const auto& hex = semimesh::io::vtk_from_canonical(Shape::Hexahedron, 2);
  const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Hexahedron, 2, NodeSet::Equispaced);
  EXPECT_EQ(ref.row(hex[18]), Eigen::RowVector3d(1, 1, 0));
  EXPECT_EQ(ref.row(hex[19]), Eigen::RowVector3d(-1, 1, 0));
}

TEST(Equispaced, GllMeshIsResampledOntoTheSameMap) {
  const int p = 4;
  const Mesh gll = two_prisms(p, NodeSet::GLL);
  const Mesh eq = semimesh::io::to_equispaced(gll);
  EXPECT_EQ(eq.node_set(), NodeSet::Equispaced);
  const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Prism, p, NodeSet::Equispaced);
  for (int i = 0; i < ref.rows(); ++i) {  // prism A maps (u, v, z) to the unit cube directly
    const Eigen::Vector3d cube(ref(i, 0), ref(i, 1), 0.5 * (ref(i, 2) + 1));
    EXPECT_LT((eq.element_coordinates(0).row(i).transpose() - quadratic_map(cube)).norm(), 1e-12) << "node " << i;
  }
}


// The streaming resampling (each node once, by the edge, face or element that owns it) against the
// reference that resamples every element whole on a copy of the mesh.
void expect_same_as_reference(const Mesh& gll, const std::string& what) {
  const semimesh::io::EquispacedNodes nodes(gll);
  const Mesh reference = semimesh::io::to_equispaced(gll);
  ASSERT_EQ(nodes.all().size(), reference.num_nodes()) << what;
  for (NodeId i = 0; i < reference.num_nodes(); ++i)
    ASSERT_LT((nodes[i] - reference.node(i)).norm(), 1e-12) << what << " node " << i;
}

// GLL meshes of orders 2-6 to resample: two prisms sharing a face, and one element of each 3D
// shape, all on a quadratic map; each with what it is.
std::vector<std::pair<Mesh, std::string>> gll_meshes() {
  std::vector<std::pair<Mesh, std::string>> meshes;
  for (int p = 2; p <= 6; ++p) {
    meshes.emplace_back(two_prisms(p, NodeSet::GLL), "two prisms, order " + std::to_string(p));
    for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron}) {
      Mesh one(p, NodeSet::GLL);
      const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(shape, p, NodeSet::GLL);
      std::vector<NodeId> ids;
      for (int i = 0; i < ref.rows(); ++i) ids.push_back(one.add_node(quadratic_map(ref.row(i).transpose())));
      one.add_element(shape, ids);
      meshes.emplace_back(std::move(one), "one element, shape " + std::to_string(int(shape)) + ", order " + std::to_string(p));
    }
  }
  return meshes;
}

TEST(Equispaced, EachNodeResampledByItsOwnerMatchesWholeElementResampling) {
  for (const auto& [mesh, what] : gll_meshes()) expect_same_as_reference(mesh, what);
}

// In place (the pipeline's writers): the same positions as the copy, bit for bit, read from the
// mesh's own array, and the mesh's GLL positions back to round-off afterwards.
void expect_in_place_same_as_copy(const Mesh& gll, const std::string& what) {
  const semimesh::io::EquispacedNodes copy(gll);
  Mesh moved = gll;
  {
    const semimesh::io::EquispacedNodes in_place(moved, semimesh::io::EquispacedNodes::InPlace{});
    ASSERT_EQ(&in_place.all(), &moved.nodes()) << what;
    for (NodeId i = 0; i < gll.num_nodes(); ++i) ASSERT_EQ(in_place[i], copy[i]) << what << " node " << i;
  }
  double scale = 0;
  for (const Eigen::Vector3d& x : gll.nodes()) scale = std::max(scale, x.norm());
  for (NodeId i = 0; i < gll.num_nodes(); ++i)
    ASSERT_LT((moved.node(i) - gll.node(i)).norm(), 1e-13 * scale) << what << " node " << i << " not moved back";
}

TEST(Equispaced, InPlaceMatchesTheCopyAndMovesTheNodesBack) {
  for (const auto& [mesh, what] : gll_meshes()) expect_in_place_same_as_copy(mesh, what);
}

// The interior nodes get back the very positions they had (kept, not resampled back).
TEST(Equispaced, InPlaceGivesTheInteriorNodesTheirExactPositionsBack) {
  for (const auto& [gll, what] : gll_meshes()) {
    Mesh moved = gll;
    { const semimesh::io::EquispacedNodes in_place(moved, semimesh::io::EquispacedNodes::InPlace{}); }
    for (NodeId id : gll.interior_pool()) ASSERT_EQ(moved.node(id), gll.node(id)) << what << " node " << id;
  }
}

// Left resampled, the mesh is the files' mesh: equispaced nodes of the same maps (the reference's
// to round-off), labelled so, its CAD attachments (whose parameters no longer match) dropped.
TEST(Equispaced, InPlaceLeftResampledIsTheEquispacedMesh) {
  const semimesh::mesh::CadAttachment on_surface{semimesh::mesh::CadAttachment::Surface, 0, 0.25, 0.5};
  for (auto [gll, what] : gll_meshes()) {
    const NodeId attached = gll.elements()[0].vertices[1];
    gll.place_node_on_cad(attached, gll.node(attached), on_surface);
    const Mesh reference = semimesh::io::to_equispaced(gll);
    Mesh moved = gll;
    {
      semimesh::io::EquispacedNodes in_place(moved, semimesh::io::EquispacedNodes::InPlace{});
      in_place.leave_resampled();
    }
    EXPECT_EQ(moved.node_set(), NodeSet::Equispaced) << what;
    EXPECT_EQ(moved.cad_attachment(attached).kind, semimesh::mesh::CadAttachment::None) << what;
    ASSERT_EQ(moved.num_nodes(), reference.num_nodes()) << what;
    for (NodeId i = 0; i < reference.num_nodes(); ++i)
      ASSERT_LT((moved.node(i) - reference.node(i)).norm(), 1e-12) << what << " node " << i;
  }
  // Nothing resampled (equispaced already): nothing changes.
  Mesh eq = two_prisms(3);
  const NodeId attached = eq.elements()[0].vertices[0];
  eq.place_node_on_cad(attached, eq.node(attached), on_surface);
  const std::vector<Eigen::Vector3d> before = eq.nodes();
  {
    semimesh::io::EquispacedNodes in_place(eq, semimesh::io::EquispacedNodes::InPlace{});
    in_place.leave_resampled();
  }
  EXPECT_EQ(eq.nodes(), before);
  EXPECT_EQ(eq.cad_attachment(attached).kind, semimesh::mesh::CadAttachment::Surface);
}

TEST(Equispaced, AnEquispacedMeshIsNotCopied) {
  const Mesh eq = two_prisms(3);
  const semimesh::io::EquispacedNodes nodes(eq);
  EXPECT_EQ(&nodes.all(), &eq.nodes());
}

}  // namespace
