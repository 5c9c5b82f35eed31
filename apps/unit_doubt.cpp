#include "unit_doubt.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <utility>

namespace semimesh::app {
namespace {

constexpr double kShortestChord = 0.05;  // metres
constexpr double kLongestChord = 100.0;

// Metres per unit, for the labels the occ backend gives (read_shape.cpp).
constexpr std::array<std::pair<const char*, double>, 7> kUnits = {{
    {"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}, {"km", 1e3}, {"um", 1e-6}, {"in", 0.0254}, {"ft", 0.3048}}};

std::optional<double> metres_per(const std::string& unit) {
  for (const auto& [label, metres] : kUnits)
    if (unit == label) return metres;
  return std::nullopt;
}

}  // namespace

std::optional<UnitDoubt> doubt_unit(double chord, const std::string& unit) {
  const std::optional<double> metres = metres_per(unit);
  if (!metres || !(chord > 0.0)) return std::nullopt;
  const double declared = chord * *metres;
  if (declared >= kShortestChord && declared <= kLongestChord) return std::nullopt;
  const double middle = std::sqrt(kShortestChord * kLongestChord);
  const char* best = nullptr;
  double best_miss = 0.0;
  for (const auto& [label, per] : kUnits) {
    const double miss = std::abs(std::log(chord * per / middle));
    if (!best || miss < best_miss) best = label, best_miss = miss;
  }
  return UnitDoubt{best, fmt::format("the root chord is {:.4g} {} = {:.4g} m, outside the {:.3g} m to {:.3g} m of a wing; "
                                     "read as {} it is {:.4g} m",
                                     chord, unit, declared, kShortestChord, kLongestChord, best,
                                     chord * *metres_per(best))};
}

}  // namespace semimesh::app
