// SoftGiFrame's static-transfer buffers (render.static_transfer; layouts.h kExponentiateBindStatic*):
// prt::StaticTransferField packed for exponentiate.comp's static-transfer variants.
#include <cstring>
#include <vector>

#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "prt/static_field.h"
#include "prt/visibility_grid.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

std::uint32_t float_bits(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

float bits_float(std::uint32_t bits) {
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

template <class T>
Result<Buffer> storage_with(Context& context, const std::vector<T>& values) {
  return create_buffer_with_data(context, as_bytes(std::span<const T>(values)),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

}  // namespace

Status SoftGiFrame::set_static_transfer(const prt::StaticTransferField* field, std::span<const float> records,
                                        const prt::VisibilityGrid* visibility) {
  const int order = config_.render.sh_order;
  std::vector<glm::vec4> positions;
  std::vector<gpu_layout::StaticTriangle> triangles;
  std::vector<std::uint32_t> grid(gpu_layout::kStaticGridHeader, 0u);
  std::vector<float> packed_records;
  if (field != nullptr && field->grid.size.x > 0) {
    if (field->order != order)
      return make_error("frame: static transfer of order " + std::to_string(field->order) + ", the frame's is " +
                        std::to_string(order));
    if (records.size() != field->positions.size() * prt::static_record_floats(order))
      return make_error("frame: " + std::to_string(records.size()) + " static record floats for " +
                        std::to_string(field->positions.size()) + " vertices");
    positions.reserve(field->positions.size());
    for (const glm::vec3& p : field->positions) positions.emplace_back(p, 1.0f);
    triangles.reserve(field->triangles.size());
    for (std::size_t t = 0; t < field->triangles.size(); ++t)
      triangles.push_back({glm::vec4(field->triangle_normals[t], 0.0f), glm::uvec4(field->triangles[t], 0u)});
    const prt::StaticGrid& g = field->grid;
    grid = {float_bits(g.origin.x), float_bits(g.origin.y), float_bits(g.origin.z), float_bits(g.cell),
            g.size.x, g.size.y, g.size.z, 0u};
    grid.insert(grid.end(), g.cell_first.begin(), g.cell_first.end());
    grid.insert(grid.end(), g.cell_triangles.begin(), g.cell_triangles.end());
    packed_records.assign(records.begin(), records.end());
  }
  std::vector<float> packed_visibility(gpu_layout::kStaticVisibilityHeader, 0.0f);  // size 0: no grid
  if (visibility != nullptr && visibility->size.x > 0) {
    if (visibility->order != order)
      return make_error("frame: visibility grid of order " + std::to_string(visibility->order) + ", the frame's is " +
                        std::to_string(order));
    const glm::uvec3 n = visibility->size;
    packed_visibility = {visibility->origin.x, visibility->origin.y, visibility->origin.z, visibility->spacing,
                         bits_float(n.x), bits_float(n.y), bits_float(n.z), 0.0f};
    packed_visibility.insert(packed_visibility.end(), visibility->values.begin(), visibility->values.end());
  }
  // Storage buffers may not be empty: one unused element each when there is no field.
  if (positions.empty()) positions.emplace_back(0.0f);
  if (triangles.empty()) triangles.push_back({});
  if (packed_records.empty()) packed_records.push_back(0.0f);
  StaticTransfer made;
  auto p = storage_with(context_, positions);
  if (!p) return p.error();
  auto t = storage_with(context_, triangles);
  if (!t) return t.error();
  auto g = storage_with(context_, grid);
  if (!g) return g.error();
  auto r = storage_with(context_, packed_records);
  if (!r) return r.error();
  auto v = storage_with(context_, packed_visibility);
  if (!v) return v.error();
  made.positions = std::move(*p);
  made.triangles = std::move(*t);
  made.grid = std::move(*g);
  made.records = std::move(*r);
  made.visibility = std::move(*v);
  static_ = std::move(made);
  return {};
}

std::size_t SoftGiFrame::static_transfer_bytes() const {
  return std::size_t(static_.positions.size() + static_.triangles.size() + static_.grid.size() + static_.records.size() +
                     static_.visibility.size());
}

}  // namespace proxygi::gpu
