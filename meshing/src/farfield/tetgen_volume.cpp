#include "tetgen_volume.hpp"

#include "semimesh/farfield/detail/boundary_crossing.hpp"
#include "semimesh/farfield/detail/flat_tet.hpp"
#include "semimesh/farfield/detail/short_edge.hpp"
#include "semimesh/farfield/detail/untie_boundary.hpp"

#include "semimesh/farfield/far_field.hpp"

#define TETLIBRARY
#include <tetgen.h>

#include <Eigen/Geometry>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <future>
#include <optional>
#include <system_error>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <sstream>
#include <string>

namespace semimesh::farfield {
namespace {

// TetGen's exit codes (tetgen.h, terminatetetgen()) as advice a user can act on.
std::string explain_tetgen_code(int code) {
  switch (code) {
    case 1: return "out of memory (lower the far-field resolution or raise box_size / wall_size)";
    case 2: return "internal error in TetGen";
    case 3: return "the far-field boundary intersects itself (skin, pyramids, wall and box faces cross; is the near "
                   "field too thick near the box or the wall, or are pyramids too tall?)";
    case 4: return "a very small input feature was detected (nearly coincident boundary points)";
    case 5: return "two boundary facets are very close to each other (skin close to itself or to the box?)";
    case 10: return "invalid input (a boundary triangle with repeated or out-of-range points)";
    default: return "unknown failure";
  }
}

// Where the boundary crosses itself, as a clause for an error message (empty if no crossing).
std::string locate_problem(const TetgenInput& input) {
  const auto crossing = find_crossing(input.points, input.triangles);
  if (!crossing) return "";
  const auto part_of = [&](std::size_t triangle) -> std::string {
    for (const auto& [end, name] : input.parts)
      if (triangle < end) return name;
    return "";
  };
  const std::string edge_part = part_of(crossing->edge_triangle), pierced_part = part_of(crossing->pierced_triangle);
  std::ostringstream out;
  out << "; boundary triangle " << crossing->edge_triangle << (edge_part.empty() ? "" : " (" + edge_part + ")")
      << " crosses boundary triangle " << crossing->pierced_triangle
      << (pierced_part.empty() ? "" : " (" + pierced_part + ")") << " at (" << crossing->point.x() << ", "
      << crossing->point.y() << ", " << crossing->point.z() << ")";
  if (!edge_part.empty() && edge_part == pierced_part && edge_part == input.parts.front().second)
    out << ": the near field's layer meets itself there, so the body is thinner there than the layers on its two "
           "sides (a knife-edge or pointed tip, a narrow gap): a smaller nearfield.thickness, or for a CAD file "
           "geometry.body_cut to cut such a tip blunt";
  return out.str();
}

// TetGen 1.5.0 replaces an input point by a neighbour closer than its tolerance (-T, 1e-8, which
// we keep) times the diagonal of the input's bounding box, warning only; the boundary's facets then
// repeat a point and it fails, crashing as it reports. Seen at 10^7 elements: a wake of 117 cells
// growing by 1.15 starts with a cell of 2.4e-8, under the 3.1e-7 of a box of diagonal 30.6, and
// TetGen replaced 152,130 of the 1.58 M boundary points. Such neighbours are ends of an edge.
constexpr double kTetgenRelativeTolerance = 1e-8;

// The refusal of a boundary with an edge TetGen would collapse, saying where the edge is.
std::string describe_short_edge(const TetgenInput& input, const ShortEdge& edge) {
  const Eigen::Vector3d& at = input.points[edge.from];
  std::ostringstream out;
  out << "the far-field boundary has an edge of length " << edge.length << " at (" << at.x() << ", " << at.y()
      << ", " << at.z() << "), shorter than TetGen's merge distance " << edge.tolerance << " (" << kTetgenRelativeTolerance
      << " of the boundary's bounding-box diagonal): TetGen would merge its ends and fail. Coarsen what makes it "
         "(a wake's first streamwise cell is length * (growth - 1) / (growth^layers - 1): with more layers, lower "
         "its growth)";
  return out.str();
}

// A tet whose six times volume is under this share of its longest edge cubed is flat to round-off
// (the far field's sound tets, slivers included, stay above ~1e-7; round-off gives ~1e-16).
// TetGen leaves such tets where boundary points are coplanar, even collinear, but for round-off
// (far_field.cpp, vary_apex_heights: where it cannot refine one it aborts); their sign is
// round-off, which any later move of a vertex by round-off turns over. Fuselage sweep seed 5
// run 18: the V of a sharp edge's two layer edges where the wake's outflow face meets its tip face,
// cut at equal steps (the wake's layer ratio 1 there); five tets 6 V / L^3 ~ 1e-16 on its cut
// nodes (one with a point TetGen added), and the weld, putting those nodes on the split's
// (~4e-16 away), turned some over.
constexpr double kFlatRelativeVolume = 1e-12;

// The refusal of TetGen's answer with a flat tet, saying where it is.
std::string describe_flat_tet(const std::vector<Eigen::Vector3d>& points, const std::array<int, 4>& tet,
                              const FlatTet& flat, int num_boundary_points) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  int on_boundary = 0;
  for (int v : tet) centre += 0.25 * points[v], on_boundary += v < num_boundary_points;
  std::ostringstream out;
  out << "TetGen made a tetrahedron of zero volume to round-off (6 V / L^3 = " << flat.relative << ") at ("
      << centre.x() << ", " << centre.y() << ", " << centre.z() << "), " << on_boundary
      << " of its 4 vertices on the boundary, where boundary points are coplanar or collinear but for round-off "
         "(as the nodes cut on a sharp trailing edge's layer edges at the wake's outflow end); its sign would turn "
         "with round-off. Change the sizes or layers slightly (e.g. wake.ratio_end, wake.layers)";
  return out.str();
}

struct TetgenRun {
  int code = 0;                      // TetGen's exit code (0: success)
  bool crashed = false;              // the child process died or sent a truncated answer
  std::string crash_description;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> tets;
};

// Reads exactly `bytes` into data; false when the pipe ends first.
bool read_all(int fd, void* data, std::size_t bytes) {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::read(fd, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

// Reads the pipe to its end.
void drain(int fd) {
  char chunk[4096];
  for (;;) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
  }
}

void write_all(int fd, const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::write(fd, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(101);
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
}

// TetGen runs in a forked child: TetGen 1.5.0 (Debian's) frees its memory pools in
// terminatetetgen() and again in the destructor that runs while its error code is thrown, so any
// TetGen failure would crash the whole program. The child sends back, through a pipe,
// [int code, int points, int tets, double xyz[points][3], int corners[tets][4]].
// `beside` runs on another thread while the child works (forked first: from one thread).
TetgenRun tetrahedralize_in_child(std::string& switches, tetgenio& in, bool quiet, const BesideChild& beside) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) throw FarFieldError(std::string("cannot create a pipe for TetGen: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    throw FarFieldError(std::string("cannot start a process for TetGen: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(pipe_fds[0]);
    if (quiet) ::freopen("/dev/null", "w", stderr);  // a failed assertion's message, when a retry follows
    tetgenio out;
    int header[3] = {0, 0, 0};
    try {
      tetrahedralize(switches.data(), &in, &out);
      header[1] = out.numberofpoints;
      header[2] = out.numberoftetrahedra;
    } catch (int code) {
      header[0] = code;
    }
    write_all(pipe_fds[1], header, sizeof header);
    if (header[0] == 0) {  // each array in one write: a call per tetrahedron cost a tenth of TetGen's time
      write_all(pipe_fds[1], out.pointlist, sizeof(REAL) * 3 * header[1]);
      std::vector<int> corners(4 * static_cast<std::size_t>(header[2]));
      for (int t = 0; t < header[2]; ++t)
        std::copy_n(out.tetrahedronlist + t * out.numberofcorners, 4, corners.begin() + 4 * t);
      write_all(pipe_fds[1], corners.data(), sizeof(int) * corners.size());
    }
    ::_exit(0);  // no atexit handlers or destructors of the parent's state in the child
  }
  ::close(pipe_fds[1]);
  std::atomic<bool> stop{false};
  std::future<void> beside_run;
  if (beside) {
    try {
      beside_run = std::async(std::launch::async, [&] {
        // The lowest priority for this thread (its own on Linux: std::async's thread is new): on a
        // core that TetGen leaves idle it runs at full speed; where another job takes that core,
        // TetGen's process (which the run waits for) goes first and this work is mostly left to
        // the stages after, instead of delaying TetGen's answer.
        ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
        try {
          beside(stop);
        } catch (...) {  // speculative: the stages after compute without it
        }
      });
    } catch (const std::system_error&) {  // no thread to be had: TetGen alone, as before
    }
  }
  // The answer is read straight into its arrays; a short read (the child died) leaves it truncated.
  int header[3] = {0, 0, 0};
  const bool whole_header = read_all(pipe_fds[0], header, sizeof header);
  TetgenRun run;
  bool whole_answer = whole_header && (header[0] != 0 || (header[1] >= 0 && header[2] >= 0));
  if (whole_header && header[0] == 0 && header[1] >= 0 && header[2] >= 0) {
    run.points.resize(static_cast<std::size_t>(header[1]));
    run.tets.resize(static_cast<std::size_t>(header[2]));
    static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double) && sizeof(std::array<int, 4>) == 4 * sizeof(int));
    whole_answer = read_all(pipe_fds[0], run.points.data(), sizeof(double) * 3 * run.points.size()) &&
                   read_all(pipe_fds[0], run.tets.data(), sizeof(int) * 4 * run.tets.size());
  }
  drain(pipe_fds[0]);  // whatever else the child wrote: it must not block on a full pipe
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  stop = true;
  if (beside_run.valid()) beside_run.wait();

  if (WIFSIGNALED(status)) {
    run = TetgenRun();
    run.crashed = true;
    run.crash_description = std::string("TetGen crashed (signal ") + std::to_string(WTERMSIG(status)) + ", " +
                            strsignal(WTERMSIG(status)) + ")";
    return run;
  }
  if (!whole_header) {
    run.crashed = true;
    run.crash_description = "TetGen's process ended without an answer";
    return run;
  }
  run.code = header[0];
  if (run.code != 0) return run;
  if (!whole_answer) {
    run = TetgenRun();
    run.crashed = true;
    run.crash_description = "TetGen's answer is truncated";
  }
  return run;
}

// TetGen's answer for the input's triangles on `given` points (the input's, or those moved off
// their ties): its points and tets, each tet turned to positive volume at `given`. Throws
// FarFieldError when TetGen fails or moved or dropped a given point.
TetgenOutput tetgen_answer(const TetgenInput& input, const std::vector<Eigen::Vector3d>& given, bool quiet,
                           const BesideChild& beside) {
  const int num_points = static_cast<int>(given.size());
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = num_points;
  in.pointlist = new REAL[3 * num_points];
  for (int i = 0; i < num_points; ++i) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = given[i][k];
  }
  in.numberoffacets = static_cast<int>(input.triangles.size());
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    facet.numberofholes = 0;
    facet.holelist = nullptr;
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = input.triangles[f][k];
  }

  std::ostringstream switches;
  switches << "pYQq" << input.radius_edge_ratio;
  if (input.max_volume > 0) switches << "a" << input.max_volume;
  if (input.max_added_points >= 0) switches << "S" << input.max_added_points;
  std::string buffer = switches.str();

  const auto start = std::chrono::steady_clock::now();
  const TetgenRun run = tetrahedralize_in_child(buffer, in, quiet, beside);
  TetgenOutput result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (run.crashed)
    throw FarFieldError("TetGen failed (switches '" + switches.str() + "'): " + run.crash_description +
                        "; TetGen 1.5.0 crashes while reporting an input error, which usually means the far-field "
                        "boundary intersects itself or two boundary facets nearly touch" + locate_problem(input));
  if (run.code != 0)
    throw FarFieldError("TetGen failed (code " + std::to_string(run.code) + ", switches '" + switches.str() +
                        "'): " + explain_tetgen_code(run.code) + locate_problem(input));

  if (static_cast<int>(run.points.size()) < num_points)
    throw FarFieldError("TetGen returned " + std::to_string(run.points.size()) + " points for " +
                        std::to_string(num_points) + " boundary points: it dropped boundary points");
  result.points = run.points;
  for (int i = 0; i < num_points; ++i)
    if (result.points[i] != given[i])
      throw FarFieldError("TetGen moved boundary point " + std::to_string(i) + "; the boundary must be kept exactly");

  result.tets.resize(run.tets.size());
  for (std::size_t t = 0; t < run.tets.size(); ++t) {
    std::array<int, 4> tet = run.tets[t];
    const Eigen::Vector3d& p0 = result.points[tet[0]];
    const double volume6 =
        (result.points[tet[1]] - p0).cross(result.points[tet[2]] - p0).dot(result.points[tet[3]] - p0);
    if (volume6 < 0) std::swap(tet[2], tet[3]);
    result.tets[t] = tet;
  }
  return result;
}

// TetGen's answer on the boundary moved off its ties, taken on the true points when every tet
// stays positive and none flat there; else none (the caller runs TetGen on the true points).
std::optional<TetgenOutput> untied_answer(const TetgenInput& input, const BesideChild& beside) {
  TetgenOutput result;
  try {
    result = tetgen_answer(input, untie_boundary(input.points, input.triangles, input.untie), /*quiet=*/true, beside);
  } catch (const FarFieldError&) {
    return std::nullopt;
  }
  std::copy(input.points.begin(), input.points.end(), result.points.begin());
  const bool holds = !first_unpositive_tet(result.points, result.tets) &&
                     !find_flat_tet(result.points, result.tets, kFlatRelativeVolume);
  if (!holds) return std::nullopt;
  result.untied = true;
  return result;
}

}  // namespace

TetgenOutput run_tetgen(const TetgenInput& input, bool quiet, const BesideChild& beside) {
  if (const auto edge = find_edge_below_tolerance(input.points, input.triangles, kTetgenRelativeTolerance))
    throw FarFieldError(describe_short_edge(input, *edge));
  const auto start = std::chrono::steady_clock::now();
  if (input.untie > 0)
    if (std::optional<TetgenOutput> untied = untied_answer(input, beside)) return std::move(*untied);
  // `beside` ran beside the untied try, if there was one.
  TetgenOutput result = tetgen_answer(input, input.points, quiet, input.untie > 0 ? BesideChild() : beside);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (const auto flat = find_flat_tet(result.points, result.tets, kFlatRelativeVolume))
    throw FarFieldError(
        describe_flat_tet(result.points, result.tets[flat->tet], *flat, static_cast<int>(input.points.size())));
  return result;
}

}  // namespace semimesh::farfield
