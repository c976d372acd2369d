#include "study/stability_metrics.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"

namespace proxygi::study {
namespace {

bool same_size(const ref::Plane& a, const ref::Plane& b) { return a.width == b.width && a.height == b.height; }

bool selected(const ref::ReceiverMask* mask, std::size_t i) { return mask == nullptr || mask->contains(i); }

void note_error(ErrorSummary& summary, double error) {
  summary.mean += error;
  summary.max = std::max(summary.max, error);
  ++summary.pixels;
}

void finish(ErrorSummary& summary) {
  if (summary.pixels > 0) summary.mean /= double(summary.pixels);
}

}  // namespace

void BoundsCounts::merge(const BoundsCounts& other) {
  const bool first = pixels == 0;
  pixels += other.pixels;
  negative += other.negative;
  over_unshadowed += other.over_unshadowed;
  non_finite += other.non_finite;
  max_overshoot_u = first ? other.max_overshoot_u : std::max(max_overshoot_u, other.max_overshoot_u);
  min_value = first ? other.min_value : std::min(min_value, other.min_value);
}

BoundsCounts count_bounds(const ref::Plane& shaded, const ref::Plane& unshadowed, const ref::ReceiverMask* mask) {
  PROXYGI_CHECK(same_size(shaded, unshadowed), "count_bounds: shaded and unshadowed differ in size");
  BoundsCounts counts;
  bool any_finite = false;
  for (std::size_t i = 0; i < shaded.values.size(); ++i) {
    if (!selected(mask, i)) continue;
    ++counts.pixels;
    const double value = shaded.values[i];
    const double open = unshadowed.values[i];
    if (!std::isfinite(value)) {
      ++counts.non_finite;
      continue;
    }
    if (value < 0.0) ++counts.negative;
    if (value > open * (1.0 + kDisplayStep)) ++counts.over_unshadowed;
    const double overshoot = open > 0.0 ? (value - open) / (open * kDisplayStep) : 0.0;
    counts.max_overshoot_u = any_finite ? std::max(counts.max_overshoot_u, overshoot) : overshoot;
    counts.min_value = any_finite ? std::min(counts.min_value, value) : value;
    any_finite = true;
  }
  return counts;
}

ref::ReceiverMask shadow_mask(const ref::Plane& reference, const ref::Plane& unshadowed, double fraction) {
  PROXYGI_CHECK(same_size(reference, unshadowed), "shadow_mask: sizes differ");
  return ref::mask_where(reference.width, reference.height,
                         [&](int x, int y) { return reference.at(x, y) < (1.0 - fraction) * unshadowed.at(x, y); });
}

ref::ReceiverMask edge_band_mask(const ref::Plane& depth, int radius, double relative_jump) {
  const int w = depth.width, h = depth.height;
  std::vector<std::uint8_t> edge(std::size_t(w) * std::size_t(h), 0);
  auto discontinuous = [&](float a, float b) {
    if ((a > 0.0f) != (b > 0.0f)) return true;
    if (a <= 0.0f) return false;  // both background
    return std::abs(a - b) > relative_jump * std::min(a, b);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float d = depth.at(x, y);
      if ((x + 1 < w && discontinuous(d, depth.at(x + 1, y))) || (y + 1 < h && discontinuous(d, depth.at(x, y + 1)))) {
        edge[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
        if (x + 1 < w && discontinuous(d, depth.at(x + 1, y))) edge[std::size_t(y) * std::size_t(w) + std::size_t(x + 1)] = 1;
        if (y + 1 < h && discontinuous(d, depth.at(x, y + 1))) edge[std::size_t(y + 1) * std::size_t(w) + std::size_t(x)] = 1;
      }
    }
  return ref::mask_where(w, h, [&](int x, int y) {
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int sx = x + dx, sy = y + dy;
        if (sx >= 0 && sy >= 0 && sx < w && sy < h && edge[std::size_t(sy) * std::size_t(w) + std::size_t(sx)] != 0) return true;
      }
    return false;
  });
}

ref::ReceiverMask label_edge_band_mask(int width, int height, std::span<const int> labels, int radius) {
  PROXYGI_CHECK(labels.size() == std::size_t(width) * std::size_t(height), "label_edge_band_mask: labels do not cover the image");
  // As depths every label is positive and any change is a jump (relative_jump 0).
  ref::Plane as_depth(width, height);
  for (std::size_t i = 0; i < labels.size(); ++i) as_depth.values[i] = float(labels[i]) - float(*std::min_element(labels.begin(), labels.end())) + 1.0f;
  return edge_band_mask(as_depth, radius, 0.0);
}

ref::ReceiverMask label_mask(int width, int height, std::span<const int> labels, int label) {
  PROXYGI_CHECK(labels.size() == std::size_t(width) * std::size_t(height), "label_mask: labels do not cover the image");
  return ref::mask_where(width, height, [&](int x, int y) { return labels[std::size_t(y) * std::size_t(width) + std::size_t(x)] == label; });
}

ref::ReceiverMask contact_band_mask(const ref::Plane& distance_over_radius, double limit) {
  return ref::mask_where(distance_over_radius.width, distance_over_radius.height,
                         [&](int x, int y) { return distance_over_radius.at(x, y) < limit; });
}

ref::ReceiverMask mask_and(const ref::ReceiverMask& a, const ref::ReceiverMask& b) {
  PROXYGI_CHECK(a.width == b.width && a.height == b.height, "mask_and: sizes differ");
  ref::ReceiverMask out = a;
  for (std::size_t i = 0; i < out.receiver.size(); ++i) out.receiver[i] = (a.receiver[i] != 0 && b.receiver[i] != 0) ? 1 : 0;
  return out;
}

ref::ReceiverMask mask_and_not(const ref::ReceiverMask& a, const ref::ReceiverMask& b) {
  PROXYGI_CHECK(a.width == b.width && a.height == b.height, "mask_and_not: sizes differ");
  ref::ReceiverMask out = a;
  for (std::size_t i = 0; i < out.receiver.size(); ++i) out.receiver[i] = (a.receiver[i] != 0 && b.receiver[i] == 0) ? 1 : 0;
  return out;
}

ErrorSummary absolute_error(const ref::Plane& test, const ref::Plane& reference, const ref::ReceiverMask* mask) {
  PROXYGI_CHECK(same_size(test, reference), "absolute_error: sizes differ");
  ErrorSummary summary;
  for (std::size_t i = 0; i < test.values.size(); ++i)
    if (selected(mask, i)) note_error(summary, std::abs(double(test.values[i]) - double(reference.values[i])));
  finish(summary);
  return summary;
}

Reprojection Reprojection::identity(int width, int height) {
  Reprojection r{width, height, std::vector<int>(std::size_t(width) * std::size_t(height))};
  for (std::size_t i = 0; i < r.source.size(); ++i) r.source[i] = int(i);
  return r;
}

ErrorSummary temporal_gradient_error(const ref::Plane& x_previous, const ref::Plane& x_current, const ref::Plane& r_previous,
                                     const ref::Plane& r_current, const Reprojection& to_previous) {
  PROXYGI_CHECK(same_size(x_current, r_current) && same_size(x_previous, r_previous), "temporal_gradient_error: sizes differ");
  PROXYGI_CHECK(to_previous.source.size() == x_current.values.size(), "temporal_gradient_error: reprojection size");
  ErrorSummary summary;
  for (std::size_t p = 0; p < x_current.values.size(); ++p) {
    const int q = to_previous.source[p];
    if (q < 0) continue;
    const double dx = double(x_current.values[p]) - double(x_previous.values[std::size_t(q)]);
    const double dr = double(r_current.values[p]) - double(r_previous.values[std::size_t(q)]);
    note_error(summary, std::abs(dx - dr));
  }
  finish(summary);
  return summary;
}

ErrorSummary pop_error(std::span<const ref::Plane, 3> x, std::span<const ref::Plane, 3> r, const Reprojection& to_previous,
                       const Reprojection& to_next) {
  for (int i = 0; i < 3; ++i) PROXYGI_CHECK(same_size(x[std::size_t(i)], r[std::size_t(i)]), "pop_error: sizes differ");
  PROXYGI_CHECK(to_previous.source.size() == x[1].values.size() && to_next.source.size() == x[1].values.size(),
                "pop_error: reprojection size");
  ErrorSummary summary;
  for (std::size_t p = 0; p < x[1].values.size(); ++p) {
    const int a = to_previous.source[p], b = to_next.source[p];
    if (a < 0 || b < 0) continue;
    auto acceleration = [&](std::span<const ref::Plane, 3> s) {
      return double(s[2].values[std::size_t(b)]) - 2.0 * double(s[1].values[p]) + double(s[0].values[std::size_t(a)]);
    };
    note_error(summary, std::abs(acceleration(x) - acceleration(r)));
  }
  finish(summary);
  return summary;
}

FlickerSummary flicker(std::span<const ref::Plane> frames, std::span<const Reprojection> to_frame) {
  PROXYGI_CHECK(frames.size() == to_frame.size() && !frames.empty(), "flicker: one reprojection per frame");
  const std::size_t points = frames.front().values.size();
  std::vector<double> deviations;
  for (std::size_t p = 0; p < points; ++p) {
    double sum = 0.0, sum_squares = 0.0;
    bool seen = true;
    for (std::size_t t = 0; t < frames.size() && seen; ++t) {
      const int q = to_frame[t].source[p];
      if (q < 0) {
        seen = false;
        break;
      }
      const double v = frames[t].values[std::size_t(q)];
      sum += v;
      sum_squares += v * v;
    }
    if (!seen) continue;
    const double n = double(frames.size());
    const double mean = sum / n;
    deviations.push_back(std::sqrt(std::max(0.0, sum_squares / n - mean * mean)));
  }
  FlickerSummary summary;
  summary.points = deviations.size();
  if (deviations.empty()) return summary;
  for (double d : deviations) summary.mean += d / double(deviations.size());
  std::sort(deviations.begin(), deviations.end());
  summary.max = deviations.back();
  summary.p99 = deviations[std::min(deviations.size() - 1, std::size_t(0.99 * double(deviations.size())))];
  return summary;
}

}  // namespace proxygi::study
