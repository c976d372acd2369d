#include "prt/static_shading.h"

#include <algorithm>
#include <vector>

#include "sh/basis.h"
#include "sh/product.h"

namespace proxygi::prt {
float dot_coefficients(std::span<const float> a, std::span<const float> b, std::size_t n) {
  float sum = 0.0f;
  for (std::size_t i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

float unblocked_fraction_of_blocked(int order, std::span<const float> blocked, std::span<const float> occlusion) {
  // D · 1 = √4π D_0: the cosine-weighted solid angle static geometry blocks.
  const float blocked_total = float(sh::kSqrtFourPi) * blocked[0];
  if (!(blocked_total > 1e-6f)) return 1.0f;
  return std::clamp(dot_coefficients(blocked, occlusion, std::size_t(order * order)) / blocked_total, 0.0f, 1.0f);
}

float unblocked_proxy_fraction(int order, std::span<const float> clamped_cosine, std::span<const float> shadowed,
                               std::span<const float> occlusion) {
  std::vector<float> blocked(std::size_t(order * order));
  for (std::size_t i = 0; i < blocked.size(); ++i) blocked[i] = clamped_cosine[i] - shadowed[i];
  return unblocked_fraction_of_blocked(order, blocked, occlusion);
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
        e = dot_coefficients(occlusion, product, nn);
        if (level == StaticTransferLevel::ratio) {
          const float unshadowed = dot_coefficients(receiver.clamped_cosine, light, nn);
          e = unshadowed > 0.0f ? e * dot_coefficients(t_di, light, nn) / unshadowed : 0.0f;
        }
        if (!indirect.empty()) e += dot_coefficients(indirect, receiver.clamped_cosine, nn);
        break;
      }
      case StaticTransferLevel::l1: {
        sh::product(order, light, receiver.shadowed, product);  // M_L T
        e = dot_coefficients(occlusion, product, nn);
        if (!indirect.empty()) e += dot_coefficients(indirect, receiver.shadowed, nn);
        e += kappa * (dot_coefficients(t_di, light, nn) - dot_coefficients(receiver.shadowed, light, nn));
        break;
      }
    }
    out[c] = std::max(e, 0.0f);
  }
  return out;
}

}  // namespace proxygi::prt
