#pragma once
// Precomputed radiance transfer for static receivers (Sloan, Kautz, Snyder 2002, §4.1 and §5):
// per vertex of prt/surfaces.h, the shadowed diffuse transfer T_DS and the interreflected T_DI,
// computed with Embree on the CPU (no Vulkan).
//
// Conventions (sh/basis.h): SH order n, n² coefficients per vector. Transfer is in irradiance
// units: E = T · L for lighting L (radiance SH), the vertex's exit radiance is albedo/π · E, so an
// unoccluded vertex has T_DS = H(N) (sh/convolution.h, not divided by π).
//   T_DS = H(N) − proj(H_N (1 − V))                    the blocked part is estimated, H(N) exact
//   T_DI = T_DS + Σ_b T^b,  T^b_p = (1/K) Σ_{blocked k} ρ_q T^{b−1}_q     (per rgb channel)
// over K cosine-weighted directions s_k (weight π/K each), q the first hit along s_k, T^{b−1}_q
// interpolated barycentrically from q's triangle (T^0 = T_DS). Estimating only the blocked part
// makes unoccluded receivers exact and H(N) − T_DS = proj(H_N (1 − V)) exactly what the L1 level's
// κ needs (prt/static_shading.h). Hits on a surface's back side (against its vertex normals) carry
// no light (closed or ground-standing meshes). The outer ground (beyond the meshed patch) has
// T^0 = H(+Y) and no bounce light of its own.
//
// Rays leave a vertex 1 mm toward its one-ring's centroid (and 1e-4 m off the surface), so a
// vertex on a seam (a floor vertex at a wall's foot, a corner) does not leak behind the other surface.
//
// Determinism: vertex v of surface s uses a Hammersley set Cranley–Patterson rotated by a hash
// of (seed, s, v), so results do not depend on the thread count or on scheduling.
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "prt/surfaces.h"

namespace proxygi::prt {

inline constexpr int kMinDirections = 16;
inline constexpr int kMaxDirections = 65536;
inline constexpr int kMaxBounces = 8;

struct TransferSettings {
  int order = 4;          // settings::kMinShOrder..kMaxShOrder (the proxy method's range)
  int directions = 1024;  // K per vertex and pass, kMinDirections..kMaxDirections
  int bounces = 2;        // interreflection passes after the shadow pass, 0..kMaxBounces
  std::uint32_t seed = 1;
  bool operator==(const TransferSettings&) const = default;
};

struct SurfaceTransfer {
  std::vector<float> shadowed;        // T_DS: vertex count × n²
  std::vector<float> interreflected;  // T_DI: vertex count × 3 × n² (r, g, b vectors per vertex)
};

struct TransferSet {
  int order = 0;
  std::vector<SurfaceTransfer> surfaces;  // one per StaticReceivers::surfaces, same order
  std::uint64_t rays = 0;                 // rays traced (all passes)
  double seconds = 0.0;                   // wall time of the precompute
  std::size_t bytes() const;              // memory of the stored vectors
};

// Called from worker threads (serialized): stage is "shadow" or "bounce <b>"; done of total vertices.
using Progress = std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

// Validates the settings ("prt.order 9: must be in 3..6") and the surfaces (normals per position,
// indices in range: "ground: index 7 out of range (4 vertices)"). threads <= 0: hardware threads.
Result<TransferSet> compute_transfer(const StaticReceivers& receivers, const TransferSettings& settings,
                                     const Progress& progress = {}, int threads = 0);

}  // namespace proxygi::prt
