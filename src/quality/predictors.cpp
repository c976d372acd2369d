#include "quality/predictors.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"
#include "quality/calibration.h"

namespace proxygi::quality {
namespace {

constexpr int kBands = 6;  // bands 0..5: the chart's references' lighting

int scale_index(int k) {
  for (std::size_t i = 0; i < settings::kReceiverScales.size(); ++i)
    if (settings::kReceiverScales[i] == k) return int(i);
  PROXYGI_CHECK(false, "receiver scale is not one of kReceiverScales");
  return 0;
}

}  // namespace

std::array<double, 4> energy_above(std::span<const double> lighting) {
  PROXYGI_CHECK(lighting.size() >= std::size_t(kBands * kBands), "energy_above needs an order-6 SH vector");
  std::array<double, kBands> band{};
  for (int l = 0; l < kBands; ++l)
    for (int m = -l; m <= l; ++m) band[std::size_t(l)] += lighting[std::size_t(l * (l + 1) + m)] * lighting[std::size_t(l * (l + 1) + m)];
  double total = 0.0;
  for (double e : band) total += e;
  std::array<double, 4> out{};
  if (!(total > 0.0)) return out;
  for (int n = settings::kMinShOrder; n <= settings::kMaxShOrder; ++n) {
    double above = 0.0;
    for (int l = n; l < kBands; ++l) above += band[std::size_t(l)];
    out[std::size_t(n - settings::kMinShOrder)] = above / total;
  }
  return out;
}

double order_ratio(int order, const std::array<double, 4>& energy) {
  PROXYGI_CHECK(order >= settings::kMinShOrder && order <= settings::kMaxShOrder, "order out of range");
  const std::size_t i = std::size_t(order - settings::kMinShOrder);
  const double chart = calibration::kChartEnergyAbove[i];
  const double scale = chart > 0.0 ? std::min(energy[i] / chart, calibration::kMaxEnergyScale) : 1.0;
  return 1.0 + (calibration::kOrderRatio[i] - 1.0) * scale;
}

double scale_ratio(int k, settings::Upsampling upsampling, double radius_px) {
  PROXYGI_CHECK(radius_px > 0.0, "projected radius must be > 0");
  scale_index(k);
  if (k == 1) return 1.0;  // receivers at every pixel: nothing to upsample
  const auto& table = upsampling == settings::Upsampling::bilinear ? calibration::kScaleRatioBilinear
                                                                    : calibration::kScaleRatioBilateral;
  const double x = std::log2(double(k) * calibration::kReferenceRadiusPx / radius_px);
  if (x <= 0.0) return 1.0;
  const double last = double(table.size() - 1);
  if (x >= last) return table.back() * std::exp(std::log(table.back() / table[table.size() - 2]) * (x - last));
  const int i = int(std::floor(x));
  const double t = x - double(i);
  return std::exp((1.0 - t) * std::log(table[std::size_t(i)]) + t * std::log(table[std::size_t(i + 1)]));
}

double floor_from_fit(std::optional<double> outside_volume_ratio) {
  if (!outside_volume_ratio) return calibration::kUnknownFloor;
  return std::clamp(calibration::kFloorIntercept + calibration::kFloorSlope * *outside_volume_ratio,
                    calibration::kMinFloor, calibration::kMaxFloor);
}

double predict_error(double floor, const std::array<double, 4>& energy, int order, int k,
                     settings::Upsampling upsampling, double radius_px) {
  return floor * order_ratio(order, energy) * scale_ratio(k, upsampling, radius_px);
}

double predicted_ms(int order, int k, settings::Upsampling upsampling) {
  PROXYGI_CHECK(order >= settings::kMinShOrder && order <= settings::kMaxShOrder, "order out of range");
  return calibration::kChartMs[order - settings::kMinShOrder][scale_index(k)]
                              [upsampling == settings::Upsampling::bilinear ? 0 : 1];
}

}  // namespace proxygi::quality
