#include "prt/static_shading.h"

#include <algorithm>
#include <vector>

#include "sh/basis.h"
#include "sh/product.h"

namespace proxygi::prt {
namespace {

float dot(std::span<const float> a, std::span<const float> b, std::size_t n) {
  float sum = 0.0f;
  for (std::size_t i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

}  // namespace

float unblocked_proxy_fraction(int order, std::span<const float> clamped_cosine, std::span<const float> shadowed,
                               std::span<const float> occlusion) {
  const std::size_t nn = std::size_t(order * order);
  // (H − T) · 1 = √4π (H − T)_0: the cosine-weighted solid angle static geometry blocks.
  const float blocked = float(sh::kSqrtFourPi) * (clamped_cosine[0] - shadowed[0]);
  if (!(blocked > 1e-6f)) return 1.0f;
  float open = 0.0f;
  for (std::size_t i = 0; i < nn; ++i) open += (clamped_cosine[i] - shadowed[i]) * occlusion[i];
  return std::clamp(open / blocked, 0.0f, 1.0f);
}

glm::vec3 shade_static_receiver(int order, StaticTransferLevel level, const StaticReceiverSh& receiver,
                                const std::array<std::span<const float>, 3>& lighting, std::span<const float> occlusion,
                                const std::array<std::span<const float>, 3>& proxy_indirect) {
  const std::size_t nn = std::size_t(order * order);
  std::vector<float> product(nn);
  const float kappa = level == StaticTransferLevel::l1
                          ? unblocked_proxy_fraction(order, receiver.clamped_cosine, receiver.shadowed, occlusion)
                          : 1.0f;
  glm::vec3 out(0.0f);
  for (int c = 0; c < 3; ++c) {
    const std::span<const float> light = lighting[std::size_t(c)];
    const std::span<const float> indirect = proxy_indirect[std::size_t(c)];
    const std::span<const float> t_di = receiver.interreflected[std::size_t(c)];
    float e = 0.0f;
    switch (level) {
      case StaticTransferLevel::l0:
      case StaticTransferLevel::ratio: {
        sh::product(order, light, receiver.clamped_cosine, product);  // M_L H = LH(N)
        e = dot(occlusion, product, nn);
        if (level == StaticTransferLevel::ratio) {
          const float unshadowed = dot(receiver.clamped_cosine, light, nn);
          e = unshadowed > 0.0f ? e * dot(t_di, light, nn) / unshadowed : 0.0f;
        }
        if (!indirect.empty()) e += dot(indirect, receiver.clamped_cosine, nn);
        break;
      }
      case StaticTransferLevel::l1: {
        sh::product(order, light, receiver.shadowed, product);  // M_L T
        e = dot(occlusion, product, nn);
        if (!indirect.empty()) e += dot(indirect, receiver.shadowed, nn);
        e += kappa * (dot(t_di, light, nn) - dot(receiver.shadowed, light, nn));
        break;
      }
    }
    out[c] = std::max(e, 0.0f);
  }
  return out;
}

}  // namespace proxygi::prt
