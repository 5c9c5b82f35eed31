#include "semimesh/io/pictures.hpp"

#include "semimesh/ho/basis.hpp"
#include "svg_canvas.hpp"

#include <algorithm>
#include <limits>
#include <map>

namespace semimesh::io {
namespace {

using Point = Eigen::Vector2d;
using Loop = std::vector<Point>;

struct Segment {
  Point a, b;
};

// A face of the reference element as a grid of small triangles: `n` intervals per edge, reference
// points (rows) and triangles over them. Faces are flat in reference space: barycentric
// interpolation of a triangle's vertices, bilinear of a quad's, is exact.
void face_grid(const std::vector<Eigen::Vector3d>& corners, int n, Eigen::MatrixX3d& points,
               std::vector<std::array<int, 3>>& triangles) {
  triangles.clear();
  if (corners.size() == 3) {
    std::vector<Eigen::Vector3d> rows;
    std::map<std::pair<int, int>, int> index;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        index[{i, j}] = static_cast<int>(rows.size());
        rows.push_back(corners[0] + (corners[1] - corners[0]) * i / n + (corners[2] - corners[0]) * j / n);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        triangles.push_back({index[{i, j}], index[{i + 1, j}], index[{i, j + 1}]});
        if (i + j + 1 < n) triangles.push_back({index[{i + 1, j}], index[{i + 1, j + 1}], index[{i, j + 1}]});
      }
    points.resize(static_cast<Eigen::Index>(rows.size()), 3);
    for (std::size_t k = 0; k < rows.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = rows[k].transpose();
    return;
  }
  points.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double s = double(i) / n, t = double(j) / n;
      points.row(j * (n + 1) + i) = ((1 - s) * (1 - t) * corners[0] + s * (1 - t) * corners[1] + s * t * corners[2] +
                                     (1 - s) * t * corners[3])
                                        .transpose();
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
}

// The segments where the plane x[axis] = station crosses the element's faces, in the picture plane.
// A point on the plane counts as above it, so every crossing is found once.
std::vector<Segment> cut_faces(const ho::LagrangeBasis& basis, const Eigen::MatrixX3d& nodes, int axis, double station) {
  const ho::Shape shape = basis.shape();
  const Eigen::MatrixX3d corners = ho::reference_nodes(shape, 1);
  const int n = std::max(4, 2 * basis.order());
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int first = std::min(u, v), second = std::max(u, v);
  std::vector<Segment> segments;
  Eigen::MatrixX3d grid;
  std::vector<std::array<int, 3>> triangles;
  for (const std::vector<int>& face : ho::faces(shape)) {
    std::vector<Eigen::Vector3d> c;
    for (int k : face) c.push_back(corners.row(k).transpose());
    face_grid(c, n, grid, triangles);
    const Eigen::MatrixX3d x = ho::map_points(basis, nodes, grid);
    for (const auto& t : triangles) {
      std::array<int, 3> above{}, below{};
      int na = 0, nb = 0;
      for (int k : t) (x(k, axis) >= station ? above[na++] : below[nb++]) = k;
      if (na == 0 || nb == 0) continue;
      std::vector<Point> ends;
      for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
          const int p = std::min(above[i], below[j]), q = std::max(above[i], below[j]);
          const double w = (station - x(p, axis)) / (x(q, axis) - x(p, axis));
          const Eigen::Vector3d y = x.row(p).transpose() + w * (x.row(q) - x.row(p)).transpose();
          ends.emplace_back(y[first], y[second]);
        }
      if (ends.size() == 2) segments.push_back({ends[0], ends[1]});
    }
  }
  return segments;
}

// Closed loops from the segments, joining ends closer than `tolerance`.
std::vector<Loop> chain(std::vector<Segment> segments, double tolerance) {
  std::vector<Loop> loops;
  std::vector<char> used(segments.size(), 0);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (used[s]) continue;
    used[s] = 1;
    Loop loop{segments[s].a, segments[s].b};
    for (bool grown = true; grown;) {
      grown = false;
      for (std::size_t k = 0; k < segments.size(); ++k) {
        if (used[k]) continue;
        const Point* next = nullptr;
        if ((segments[k].a - loop.back()).norm() <= tolerance) next = &segments[k].b;
        else if ((segments[k].b - loop.back()).norm() <= tolerance) next = &segments[k].a;
        if (!next) continue;
        used[k] = 1;
        loop.push_back(*next);
        grown = true;
      }
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

CutPicture svg_cut(const mesh::Mesh& mesh, int axis, double station, const Window& window, const std::string& title) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int first = std::min(u, v), second = std::max(u, v);
  const bool cropped = window[0] < window[2] && window[1] < window[3];
  struct Drawn {
    std::vector<Loop> loops;
    int region;
  };
  std::vector<Drawn> drawn;
  std::array<double, 4> box = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const mesh::Element& el = mesh.elements()[e];
    const Eigen::MatrixX3d nodes = mesh.element_coordinates(e);
    if (nodes.col(axis).minCoeff() > station || nodes.col(axis).maxCoeff() < station) continue;
    const Eigen::Vector2d lo(nodes.col(first).minCoeff(), nodes.col(second).minCoeff());
    const Eigen::Vector2d hi(nodes.col(first).maxCoeff(), nodes.col(second).maxCoeff());
    if (cropped && (hi.x() < window[0] || lo.x() > window[2] || hi.y() < window[1] || lo.y() > window[3])) continue;
    const ho::LagrangeBasis basis(el.shape, mesh.order(), mesh.node_set());
    std::vector<Segment> segments = cut_faces(basis, nodes, axis, station);
    if (segments.empty()) continue;
    drawn.push_back({chain(std::move(segments), 1e-9 * (hi - lo).norm()), el.region});
    for (const Loop& loop : drawn.back().loops)
      for (const Point& p : loop) {
        box = {std::min(box[0], p.x()), std::min(box[1], p.y()), std::max(box[2], p.x()), std::max(box[3], p.y())};
      }
  }
  if (cropped) box = window;
  if (drawn.empty()) box = {0, 0, 1, 1};

  detail::SvgCanvas canvas(box, 1000.0, title);
  const double line = drawn.size() > 20000 ? 0.15 : 0.4;
  std::map<int, bool> regions;
  for (const Drawn& d : drawn) {
    std::string path;
    for (const Loop& loop : d.loops) {
      path += "M" + canvas.at(loop.front());
      for (std::size_t i = 1; i < loop.size(); ++i) path += " L" + canvas.at(loop[i]);
      path += " Z ";
    }
    regions[d.region] = true;
    canvas.draw(fmt::format("<path class=\"element\" d=\"{}\" fill=\"{}\" fill-rule=\"evenodd\" stroke=\"#222\" "
                            "stroke-width=\"{}\"/>\n",
                            path, detail::region_colour(mesh.region_names()[d.region]), line));
  }
  double y = 44;
  for (const auto& [region, unused] : regions) {
    const std::string& name = mesh.region_names()[region];
    canvas.annotate(fmt::format("<rect x=\"{:.0f}\" y=\"{:.0f}\" width=\"14\" height=\"14\" fill=\"{}\" stroke=\"#222\"/>"
                                "<text x=\"{:.0f}\" y=\"{:.0f}\" font-family=\"sans-serif\" font-size=\"13\">{}</text>\n",
                                canvas.width() - 150, y - 11, detail::region_colour(name), canvas.width() - 130, y,
                                detail::xml_text(name)));
    y += 20;
  }
  return {canvas.svg(), drawn.size()};
}

}  // namespace semimesh::io
