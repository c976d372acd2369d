#include "ref/metrics.h"

#include <cmath>
#include <string>

namespace proxygi::ref {
namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

std::size_t ReceiverMask::count() const {
  std::size_t n = 0;
  for (std::uint8_t r : receiver) n += r != 0 ? 1 : 0;
  return n;
}

ReceiverMask mask_from_image(const image::ImageF& mask) {
  return mask_where(mask.width, mask.height, [&](int x, int y) {
    const glm::vec4& p = mask.at(x, y);
    return std::max(p.r, std::max(p.g, p.b)) * p.a > 0.5f;
  });
}

ReceiverMask mask_from_alpha(const image::ImageF& image, float threshold) {
  return mask_where(image.width, image.height, [&](int x, int y) { return image.at(x, y).a > threshold; });
}

ReceiverMask mask_where(int width, int height, const std::function<bool(int, int)>& predicate) {
  ReceiverMask mask{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height), 0)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      mask.receiver[std::size_t(y) * std::size_t(width) + std::size_t(x)] = predicate(x, y) ? 1 : 0;
  return mask;
}

Status check_comparable(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask) {
  if (test.width <= 0 || test.height <= 0) return make_error("test image is empty");
  if (test.width != reference.width || test.height != reference.height)
    return make_error("size mismatch: test is " + size_text(test.width, test.height) + ", reference is " +
                      size_text(reference.width, reference.height));
  if (mask != nullptr) {
    if (mask->width != test.width || mask->height != test.height)
      return make_error("size mismatch: mask is " + size_text(mask->width, mask->height) + ", images are " +
                        size_text(test.width, test.height));
    if (mask->count() == 0) return make_error("mask selects no receiver pixels");
  }
  return {};
}

MetricResult pool_mean(Plane map, const ReceiverMask* mask, const std::vector<std::uint8_t>* valid) {
  MetricResult result;
  double sum = 0.0;
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const bool counted = (mask == nullptr || mask->contains(i)) && (valid == nullptr || (*valid)[i] != 0);
    if (!counted) {
      map.values[i] = 0.0f;
      continue;
    }
    sum += map.values[i];
    ++result.pixels;
  }
  result.mean = result.pixels > 0 ? sum / double(result.pixels) : 0.0;
  result.map = std::move(map);
  return result;
}

double mean_luminance(const image::ImageF& image, const ReceiverMask* mask) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (mask != nullptr && !mask->contains(i)) continue;
    const glm::vec4& p = image.pixels[i];
    sum += image::rec709_luminance(p);
    ++count;
  }
  return count > 0 ? sum / double(count) : 0.0;
}

Result<MetricResult> rmse(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask) {
  if (Status ok = check_comparable(test, reference, mask); !ok) return ok.error();
  Plane squared(test.width, test.height);
  for (std::size_t i = 0; i < squared.values.size(); ++i) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(test.pixels[i][c]) - double(reference.pixels[i][c]);
      sum += d * d;
    }
    squared.values[i] = float(sum / 3.0);
  }
  MetricResult result = pool_mean(std::move(squared), mask);
  result.mean = std::sqrt(result.mean);
  for (float& v : result.map.values) v = std::sqrt(v);
  return result;
}

Result<MetricResult> relative_mse(const image::ImageF& test, const image::ImageF& reference,
                                  const ReceiverMask* mask, double epsilon) {
  if (Status ok = check_comparable(test, reference, mask); !ok) return ok.error();
  Plane relative(test.width, test.height);
  for (std::size_t i = 0; i < relative.values.size(); ++i) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c];
      const double d = double(test.pixels[i][c]) - r;
      sum += d * d / (r * r + epsilon);
    }
    relative.values[i] = float(sum / 3.0);
  }
  return pool_mean(std::move(relative), mask);
}

}  // namespace proxygi::ref
