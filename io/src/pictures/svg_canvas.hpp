// A small SVG canvas: model coordinates (two axes of the picture plane) mapped into a fixed-width
// pixel frame with the second axis pointing up, and the colours of the regions.
#pragma once

#include <Eigen/Core>

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

namespace semimesh::io::detail {

class SvgCanvas {
 public:
  /// The picture of the model rectangle {min0, min1, max0, max1}, `width` pixels wide, with room
  /// above for a title line.
  SvgCanvas(const std::array<double, 4>& box, double width, std::string title);

  /// Pixel coordinates of a model point.
  Eigen::Vector2d pixel(const Eigen::Vector2d& p) const;
  /// "x,y" in pixels of a model point (for path data).
  std::string at(const Eigen::Vector2d& p) const;
  /// Appends raw SVG inside the clipped drawing area.
  void draw(const std::string& element) { body_ += element; }
  /// Appends raw SVG outside the clip (legends, labels).
  void annotate(const std::string& element) { notes_ += element; }
  double width() const { return width_; }
  double height() const { return height_; }
  /// The whole document.
  std::string svg() const;

 private:
  std::array<double, 4> box_;
  double width_, height_, scale_;
  std::string title_, body_, notes_;
};

/// Fill colour of a region by name (the near-field blocks have fixed colours, others a palette).
std::string region_colour(const std::string& region);

/// Text safe inside SVG/XML.
std::string xml_text(const std::string& text);

}  // namespace semimesh::io::detail
