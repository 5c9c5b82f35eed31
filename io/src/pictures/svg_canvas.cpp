#include "svg_canvas.hpp"

#include <functional>

namespace semimesh::io::detail {

constexpr double kTitleHeight = 28.0;

SvgCanvas::SvgCanvas(const std::array<double, 4>& box, double width, std::string title)
    : box_(box), width_(width), title_(std::move(title)) {
  const double w = std::max(box[2] - box[0], 1e-300), h = std::max(box[3] - box[1], 1e-300);
  scale_ = width / w;
  height_ = scale_ * h;
}

Eigen::Vector2d SvgCanvas::pixel(const Eigen::Vector2d& p) const {
  return {(p.x() - box_[0]) * scale_, kTitleHeight + (box_[3] - p.y()) * scale_};
}

std::string SvgCanvas::at(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d q = pixel(p);
  return fmt::format("{:.2f},{:.2f}", q.x(), q.y());
}

std::string SvgCanvas::svg() const {
  const double total = height_ + kTitleHeight;
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.2f} {1:.2f}\">\n"
      "<title>{2}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"8\" y=\"19\" font-family=\"sans-serif\" font-size=\"15\">{2}</text>\n"
      "<clipPath id=\"frame\"><rect x=\"0\" y=\"{3:.2f}\" width=\"{4:.2f}\" height=\"{5:.2f}\"/></clipPath>\n"
      "<g clip-path=\"url(#frame)\" stroke-linejoin=\"round\">\n{6}</g>\n{7}</svg>\n",
      width_, total, xml_text(title_), kTitleHeight, width_, height_, body_, notes_);
}

std::string region_colour(const std::string& region) {
  if (region == "wing_layer") return "#7aa6d6";
  if (region == "wall_layer") return "#8cc68a";
  if (region == "junction") return "#f2a65a";
  if (region == "wake") return "#e8767a";
  if (region == "farfield") return "#e4e4e4";
  static const char* const palette[] = {"#b07aa1", "#76b7b2", "#edc948", "#9c755f", "#bab0ac"};
  return palette[std::hash<std::string>{}(region) % 5];
}

std::string xml_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace semimesh::io::detail
