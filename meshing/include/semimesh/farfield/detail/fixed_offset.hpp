// A pseudo-random offset fixed by a key: the same on every run, platform and thread count.
#pragma once

#include <Eigen/Core>

#include <cstdint>

namespace semimesh::farfield {

/// [3] in [-1, 1]^3: SplitMix64 of the key, once per coordinate.
inline Eigen::Vector3d fixed_offset(std::uint64_t key) {
  Eigen::Vector3d offset;
  for (int k = 0; k < 3; ++k) {
    key += 0x9e3779b97f4a7c15ull;
    std::uint64_t z = key;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    offset[k] = 2.0 * static_cast<double>(z >> 11) / static_cast<double>(1ull << 53) - 1.0;
  }
  return offset;
}

}  // namespace semimesh::farfield
