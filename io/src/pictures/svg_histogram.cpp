#include "semimesh/io/pictures.hpp"

#include "svg_canvas.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::io {

std::string svg_histogram(const std::map<std::string, std::vector<double>>& scaled_jacobians_by_type,
                          const std::string& title) {
  constexpr int kBins = 20;  // [0, 1] in steps of 0.05; bin -1 holds the invalid elements
  std::map<std::string, std::vector<std::size_t>> counts;
  std::size_t invalid = 0, largest = 1;
  for (const auto& [type, values] : scaled_jacobians_by_type) {
    std::vector<std::size_t>& c = counts[type];
    c.assign(kBins + 1, 0);
    for (const double q : values) {
      const int bin = !(q > 0.0) ? 0 : 1 + std::min(kBins - 1, static_cast<int>(q * kBins));
      invalid += bin == 0;
      largest = std::max(largest, ++c[bin]);
    }
  }
  // Bar heights on a log scale (counts span orders of magnitude between element types).
  const double top = std::log10(static_cast<double>(largest)) + 0.3;
  detail::SvgCanvas canvas({-2.5, -0.12 * top, kBins + 0.5, top}, 1000.0,
                           title + " (" + std::to_string(invalid) + " invalid)");
  const double group = 0.8 / std::max<std::size_t>(1, counts.size());
  int series = 0;
  static const char* const colours[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#b07aa1"};
  for (const auto& [type, c] : counts) {
    for (int bin = 0; bin <= kBins; ++bin) {
      if (c[bin] == 0) continue;
      const double x0 = bin - 1.0 - 0.4 + series * group, h = std::log10(static_cast<double>(c[bin])) + 0.3;
      canvas.draw(fmt::format("<path class=\"bar\" d=\"M{} L{} L{} L{} Z\" fill=\"{}\"><title>{} {}</title></path>\n",
                              canvas.at({x0, 0}), canvas.at({x0 + group, 0}), canvas.at({x0 + group, h}),
                              canvas.at({x0, h}), colours[series % 6], detail::xml_text(type), c[bin]));
    }
    canvas.annotate(fmt::format("<rect x=\"820\" y=\"{}\" width=\"14\" height=\"14\" fill=\"{}\"/><text x=\"840\" "
                                "y=\"{}\" font-family=\"sans-serif\" font-size=\"13\">{}</text>\n",
                                34 + 20 * series, colours[series % 6], 46 + 20 * series, detail::xml_text(type)));
    ++series;
  }
  for (int tick = 0; tick <= kBins; tick += 4) {
    const Eigen::Vector2d at = canvas.pixel({tick - 0.5, -0.1 * top});
    canvas.draw(fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-family=\"sans-serif\" font-size=\"12\">{:.1f}</text>\n",
                            at.x(), at.y(), tick / double(kBins)));
  }
  const Eigen::Vector2d label = canvas.pixel({-2.3, -0.1 * top});
  canvas.draw(fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-family=\"sans-serif\" font-size=\"12\">invalid</text>\n",
                          label.x(), label.y()));
  return canvas.svg();
}

}  // namespace semimesh::io
