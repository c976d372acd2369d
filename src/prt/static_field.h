#pragma once
// The run-time form of a scene's PRT (prt/transfer.h), and the CPU form of the static-receiver
// formula that the frame applies (exponentiate.comp's static-transfer variants, with
// static_transfer.glsl; render.static_transfer); its twin test compares against
// shade_static_direct below (prt/static_frame.h: the whole receiver).
//
// A receiver of the frame is a world point p with unit normal N (facing the viewer); it is a
// static receiver when it lies on a PRT triangle: within kStaticHitDistance of the triangle's
// plane, inside it (barycentrics ≥ −kStaticHitBarycentricSlack) and with N · n_t > kStaticHitCosine
// (n_t the geometric normal turned to the vertex normals' side, so a wall's back face does not
// take the front's transfer). The triangles are found through a uniform grid (cells of
// kStaticGridCellsPerSpacing × the subdivision spacing, each listing the triangles whose bounds
// grown by kStaticHitDistance overlap it); among the hits the one nearest the plane wins, the
// first in cell order on ties. Characters' pixels are not marked: a character point within 5 mm
// of a static surface facing the same way shades as that surface (feet soles face down: never).
//
// Per vertex the frame reads a baked record of floats (n = order, nn = n², c = r, g, b) for the
// lighting L (windowed SH of the environment, render::FrameTables::lighting; not the ground-lit
// L': the transfer already contains the ground, blocking and reflecting):
//   [0, 3nn)        u_c = M_L T_DS          (order-n truncated product, sh/product.h)
//   [3nn, 4nn)      D = H(N_v) − T_DS       (what static geometry blocks, cosine-weighted)
//   [4nn, 4nn+3)    B_c · L = (T_DI − T_DS) · L_c
//   [4nn+3, 4nn+6)  T_DI · L_c
// interpolated barycentrically at the hit (linear, so M_L of the interpolated T equals the
// interpolated u). The pass then replaces the receiver's direct E (E_ind, the proxies' bounce
// I_p · H, is kept: the order-3 gather clamps per proxy and forms no I_p vector to dot with T):
//   ratio  E = (O_p · LH(N)) · (T_DI · L) / (√4π LH(N)_0)     LH from the environment's cube set
//   l1     E = O_p · u + κ (B · L),  κ = clamp((D · O_p) / (√4π D_0), 0, 1), 1 when √4π D_0 ≤ 1e-6
// per channel, clamped at 0. Receivers that are not static keep the l0 frame.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "prt/surfaces.h"
#include "prt/transfer.h"
#include "prt/static_shading.h"
#include "sh/environment.h"
#include "shaders/shared/layouts.h"

namespace proxygi::prt {

// Defined once with the frame pass that applies them (shaders/shared/layouts.h).
inline constexpr float kStaticHitDistance = gpu_layout::kStaticHitDistance;  // m from the triangle's plane
inline constexpr float kStaticHitBarycentricSlack = gpu_layout::kStaticHitBarycentricSlack;
inline constexpr float kStaticHitCosine = gpu_layout::kStaticHitCosine;
inline constexpr float kStaticGridCellsPerSpacing = 2.0f;     // cell edge / subdivision spacing
inline constexpr std::uint32_t kStaticGridMaxCells = 1u << 21;  // the cell grows beyond this

struct StaticGrid {
  glm::vec3 origin{0.0f};  // world min corner, m
  float cell = 1.0f;       // edge, m
  glm::uvec3 size{0u};     // cells per axis (0: empty grid)
  std::vector<std::uint32_t> cell_first;     // size.x·size.y·size.z + 1 offsets into cell_triangles
  std::vector<std::uint32_t> cell_triangles; // triangle indices, ascending within a cell
};

// All PRT surfaces as one mesh with its transfer and the grid over it. Immutable once built.
struct StaticTransferField {
  int order = 0;
  std::vector<glm::vec3> positions;     // world, m (all surfaces' vertices, surface after surface)
  std::vector<glm::vec3> normals;       // unit vertex normals
  std::vector<glm::uvec3> triangles;    // into positions
  std::vector<glm::vec3> triangle_normals;  // unit geometric normals on the vertex normals' side
  std::vector<float> shadowed;          // T_DS, vertex × nn
  std::vector<float> interreflected;    // T_DI, vertex × 3 × nn
  StaticGrid grid;
  std::size_t bytes() const;            // CPU memory of the arrays above
};

// Fails when the transfer does not match the receivers (surface or vertex counts).
Result<std::shared_ptr<const StaticTransferField>> make_static_field(const StaticReceivers& receivers,
                                                                     const TransferSet& transfer, float spacing_m);

// Floats per baked vertex record (layout above).
inline constexpr std::size_t static_record_floats(int order) { return std::size_t(4 * order * order + 6); }
// The baked records of every vertex for lighting (order ≥ field.order; its first nn used).
std::vector<float> bake_static_records(const StaticTransferField& field, const sh::RgbSh& lighting);

struct StaticHit {
  std::uint32_t triangle = 0;
  glm::vec3 weights{0.0f};  // barycentric weights of the triangle's vertices 0, 1, 2
};
std::optional<StaticHit> find_static_hit(const StaticTransferField& field, const glm::vec3& p, const glm::vec3& normal);

// The record interpolated at the hit (static_record_floats values).
std::vector<float> interpolate_record(const StaticTransferField& field, std::span<const float> records,
                                      const StaticHit& hit);

// The pass's formula (above) for one static receiver: occlusion O_p (nn), lighting_lh LH(N) per
// channel from the environment's cube set (nn each). l0 is not handled here (the frame unchanged).
glm::vec3 shade_static_direct(int order, StaticTransferLevel level, std::span<const float> record,
                              std::span<const float> occlusion, const std::array<std::vector<float>, 3>& lighting_lh);

}  // namespace proxygi::prt
