#pragma once
// The PRT precomputes' deterministic sample sets (prt/transfer.cpp, prt/visibility_grid.cpp): a
// 32-bit integer hash for per-vertex / per-point seeds and the base-2 radical inverse of the
// Hammersley set.
#include <cstdint>

namespace proxygi::prt::sampling {

inline std::uint32_t hash32(std::uint32_t x) {  // lowbias32
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

inline float radical_inverse2(std::uint32_t bits) {
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x00ff00ffu) << 8) | ((bits & 0xff00ff00u) >> 8);
  bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
  return float(bits) * 2.3283064365386963e-10f;
}

}  // namespace proxygi::prt::sampling
