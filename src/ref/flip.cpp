// LDR- and HDR-FLIP; the formulas and constants are listed in flip.h.
#include "ref/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace proxygi::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95, kQf = 0.5, kW = 0.082;

using Vec3 = std::array<double, 3>;

// sRGB primaries with D65 white: rows sum to the white point (0.950428545, 1, 1.088900371).
constexpr double kRgbToXyz[3][3] = {{10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
                                    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
                                    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};
constexpr Vec3 kWhite = {kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2], 1.0,
                         kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};

Vec3 multiply(const double m[3][3], const Vec3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

struct XyzToRgb {
  double m[3][3];
  XyzToRgb() {  // inverse of kRgbToXyz by cofactors
    const auto& a = kRgbToXyz;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
        m[r][c] = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) / det;
      }
  }
};
const XyzToRgb kXyzToRgb;

// YCxCz: CIELAB with the cube root left out (linear in XYZ, so filtering it is meaningful).
Vec3 rgb_to_ycxcz(const Vec3& rgb) {
  const Vec3 xyz = multiply(kRgbToXyz, rgb);
  const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxcz_to_rgb(const Vec3& ycxcz) {
  const double y = (ycxcz[0] + 16.0) / 116.0;
  const Vec3 xyz = {(y + ycxcz[1] / 500.0) * kWhite[0], y * kWhite[1], (y - ycxcz[2] / 200.0) * kWhite[2]};
  return multiply(kXyzToRgb.m, xyz);
}

// CIELAB of linear RGB, then the Hunt adjustment (chroma scaled by 0.01 L).
Vec3 rgb_to_hunt_lab(const Vec3& rgb) {
  const Vec3 xyz = multiply(kRgbToXyz, rgb);
  constexpr double delta = 6.0 / 29.0;
  auto f = [&](double t) { return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0; };
  const double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  const double l = 116.0 * fy - 16.0;
  return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

double hyab(const Vec3& a, const Vec3& b) {
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// 1D factors of the CSF kernels: exp(-pi^2 (i/ppd)^2 / b), i in [-r, r].
std::vector<double> csf_gaussian(double b, int radius, double ppd) {
  std::vector<double> g(std::size_t(2 * radius + 1));
  for (int i = -radius; i <= radius; ++i) {
    const double x = i / ppd;
    g[std::size_t(i + radius)] = std::exp(-kPi * kPi * x * x / b);
  }
  return g;
}

double sum(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

// Filters one YCxCz channel with s(r) = sum_k a_k sqrt(pi/b_k) exp(-pi^2 r^2/b_k), normalized so
// the 2D kernel sums to 1. Each term is separable: g_k(x) g_k(y), with 2D sum S_k^2.
Plane csf_filter(const Plane& in, std::initializer_list<std::pair<double, double>> terms, int radius, double ppd) {
  std::vector<std::vector<double>> gs;
  std::vector<double> weights;
  double total = 0.0;
  for (const auto& [a, b] : terms) {
    gs.push_back(csf_gaussian(b, radius, ppd));
    const double s = sum(gs.back());
    weights.push_back(a * std::sqrt(kPi / b));
    total += weights.back() * s * s;
  }
  Plane out(in.width, in.height);
  for (std::size_t k = 0; k < gs.size(); ++k) {
    const Plane part = convolve_separable(in, scaled(gs[k], weights[k] / total), gs[k]);
    for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] += part.values[i];
  }
  return out;
}

// Normalizes positive weights to sum to 1 and negative ones to -1 (of the 1D factor; the other
// factor is a Gaussian normalized to 1, so the 2D kernel obeys the same rule).
std::vector<double> normalize_signed(std::vector<double> k) {
  double positive = 0.0, negative = 0.0;
  for (double v : k) (v > 0 ? positive : negative) += v;
  for (double& v : k) v = v > 0 ? v / positive : (v < 0 ? v / -negative : 0.0);
  return k;
}

struct FeatureKernels {
  std::vector<double> gauss, edge, point;
};

FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * kW * ppd;
  const int radius = int(std::ceil(3.0 * sigma));
  std::vector<double> g, e, p;
  double gsum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double gi = std::exp(-double(i * i) / (2.0 * sigma * sigma));
    g.push_back(gi);
    gsum += gi;
    e.push_back(-i * gi);
    p.push_back((double(i * i) / (sigma * sigma) - 1.0) * gi);
  }
  FeatureKernels k;
  for (double gi : g) k.gauss.push_back(gi / gsum);
  k.edge = normalize_signed(e);
  k.point = normalize_signed(p);
  return k;
}

double feature_norm(const Plane& along_x, const Plane& along_y, std::size_t i) {
  return std::hypot(double(along_x.values[i]), double(along_y.values[i]));
}

// LDR-FLIP map of two images already in [0, 1] linear RGB.
Plane ldr_flip_map(const image::ImageF& test, const image::ImageF& reference, double ppd,
                   const std::function<Vec3(const glm::vec4&)>& to_unit_rgb) {
  const int w = test.width, h = test.height;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  const double b_max = 0.04;  // largest CSF b parameter
  const int csf_radius = int(std::ceil(3.0 * std::sqrt(b_max / (2.0 * kPi * kPi)) * ppd));
  const FeatureKernels fk = feature_kernels(ppd);

  struct Prepared {
    std::vector<Vec3> hunt_lab;  // after CSF filtering
    Plane edge_norm, point_norm;
  };
  auto prepare = [&](const image::ImageF& image) {
    std::array<Plane, 3> opponent{Plane(w, h), Plane(w, h), Plane(w, h)};
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 o = rgb_to_ycxcz(to_unit_rgb(image.pixels[i]));
      for (int c = 0; c < 3; ++c) opponent[std::size_t(c)].values[i] = float(o[std::size_t(c)]);
    }
    const Plane y = opponent[0];
    const Plane fy = csf_filter(opponent[0], {{1.0, 0.0047}}, csf_radius, ppd);
    const Plane fcx = csf_filter(opponent[1], {{1.0, 0.0053}}, csf_radius, ppd);
    const Plane fcz = csf_filter(opponent[2], {{34.1, 0.04}, {13.5, 0.025}}, csf_radius, ppd);
    Prepared p;
    p.hunt_lab.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 rgb = ycxcz_to_rgb({fy.values[i], fcx.values[i], fcz.values[i]});
      for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
      p.hunt_lab[i] = rgb_to_hunt_lab(rgb);
    }
    Plane luminance(w, h);  // Y / Yn in [0, 1]
    for (std::size_t i = 0; i < n; ++i) luminance.values[i] = (y.values[i] + 16.0f) / 116.0f;
    const Plane ex = convolve_separable(luminance, fk.edge, fk.gauss);
    const Plane ey = convolve_separable(luminance, fk.gauss, fk.edge);
    const Plane px = convolve_separable(luminance, fk.point, fk.gauss);
    const Plane py = convolve_separable(luminance, fk.gauss, fk.point);
    p.edge_norm = Plane(w, h);
    p.point_norm = Plane(w, h);
    for (std::size_t i = 0; i < n; ++i) {
      p.edge_norm.values[i] = float(feature_norm(ex, ey, i));
      p.point_norm.values[i] = float(feature_norm(px, py, i));
    }
    return p;
  };
  const Prepared t = prepare(test);
  const Prepared r = prepare(reference);

  const double cmax = std::pow(hyab(rgb_to_hunt_lab({0, 1, 0}), rgb_to_hunt_lab({0, 0, 1})), kQc);
  const double pccmax = kPc * cmax;
  Plane map(w, h);
  for (std::size_t i = 0; i < n; ++i) {
    const double e = std::pow(hyab(r.hunt_lab[i], t.hunt_lab[i]), kQc);
    const double color = e < pccmax ? (kPt / pccmax) * e : kPt + ((e - pccmax) / (cmax - pccmax)) * (1.0 - kPt);
    const double feature_difference =
        std::max(std::abs(double(r.edge_norm.values[i]) - t.edge_norm.values[i]),
                 std::abs(double(r.point_norm.values[i]) - t.point_norm.values[i]));
    const double feature = std::pow(feature_difference / std::sqrt(2.0), kQf);
    map.values[i] = float(std::pow(color, 1.0 - feature));
  }
  return map;
}

Vec3 clamped_rgb(const glm::vec4& p) {
  auto unit = [](float v) { return v > 0.0f ? std::min(double(v), 1.0) : 0.0; };  // NaN -> 0
  return {unit(p.r), unit(p.g), unit(p.b)};
}

double luminance(const glm::vec4& p) {
  auto nonnegative = [](float v) { return v > 0.0f ? double(v) : 0.0; };
  return 0.2126 * nonnegative(p.r) + 0.7152 * nonnegative(p.g) + 0.0722 * nonnegative(p.b);
}

// ACES fit coefficients with the 0.6 pre-exposure folded in: (k0 x^2 + k1 x) / (k3 x^2 + k4 x + k5).
constexpr double kK0 = 0.6 * 0.6 * 2.51, kK1 = 0.6 * 0.03, kK3 = 0.6 * 0.6 * 2.43, kK4 = 0.6 * 0.59, kK5 = 0.14;

// Input x where the ACES curve reaches t (root of (k0 - k3 t) x^2 + (k1 - k4 t) x - k5 t = 0).
double aces_inverse(double t) {
  const double c0 = (kK1 - kK4 * t) / (kK0 - kK3 * t);
  const double c1 = (-kK5 * t) / (kK0 - kK3 * t);
  return -0.5 * c0 + std::sqrt(0.25 * c0 * c0 - c1);
}

}  // namespace

float flip_tone_map_aces(float linear, double exposure) {
  const double x = std::exp2(exposure) * (linear > 0.0f ? double(linear) : 0.0);
  if (std::isinf(x)) return 1.0f;
  const double y = (kK0 * x * x + kK1 * x) / (kK3 * x * x + kK4 * x + kK5);
  return float(std::clamp(y, 0.0, 1.0));
}

Result<MetricResult> flip_ldr(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask,
                              const FlipOptions& options) {
  if (Status ok = check_comparable(test, reference, mask); !ok) return ok.error();
  if (!(options.pixels_per_degree > 0.0)) return make_error("FLIP: pixels per degree must be positive");
  return pool_mean(ldr_flip_map(test, reference, options.pixels_per_degree, clamped_rgb), mask);
}

Result<HdrFlipResult> flip_hdr(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask,
                               const HdrFlipOptions& options) {
  if (Status ok = check_comparable(test, reference, mask); !ok) return ok.error();
  if (!(options.pixels_per_degree > 0.0)) return make_error("FLIP: pixels per degree must be positive");
  HdrFlipResult result;
  if (options.automatic_exposures) {
    std::vector<double> y(reference.pixels.size());
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = luminance(reference.pixels[i]);
    const double y_max = *std::max_element(y.begin(), y.end());
    if (y_max <= 0.0) {
      result.start_exposure = result.stop_exposure = 0.0;  // black reference: one neutral exposure
    } else {
      std::sort(y.begin(), y.end());
      const std::size_t m = y.size() / 2;
      double median = y.size() % 2 == 1 ? y[m] : 0.5 * (y[m - 1] + y[m]);
      median = std::max(median, 1e-6 * y_max);
      const double x = aces_inverse(0.85);  // t_max = t_min = 0.85
      result.start_exposure = std::log2(x / y_max);
      result.stop_exposure = std::log2(x / median);
    }
    result.exposure_count = std::max(2, int(std::ceil(result.stop_exposure - result.start_exposure)));
  } else {
    if (options.exposure_count < 1 || options.stop_exposure < options.start_exposure)
      return make_error("HDR-FLIP: need start <= stop exposure and at least one exposure");
    result.start_exposure = options.start_exposure;
    result.stop_exposure = options.stop_exposure;
    result.exposure_count = options.exposure_count;
  }

  const double step = (result.stop_exposure - result.start_exposure) / std::max(result.exposure_count - 1, 1);
  Plane maximum(test.width, test.height, 0.0f);
  image::ImageF test_ldr(test.width, test.height), reference_ldr(test.width, test.height);
  for (int k = 0; k < result.exposure_count; ++k) {
    const double exposure = result.start_exposure + k * step;
    for (std::size_t i = 0; i < test.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        test_ldr.pixels[i][c] = flip_tone_map_aces(test.pixels[i][c], exposure);
        reference_ldr.pixels[i][c] = flip_tone_map_aces(reference.pixels[i][c], exposure);
      }
    const Plane map = ldr_flip_map(test_ldr, reference_ldr, options.pixels_per_degree, clamped_rgb);
    for (std::size_t i = 0; i < map.values.size(); ++i) maximum.values[i] = std::max(maximum.values[i], map.values[i]);
  }
  result.flip = pool_mean(std::move(maximum), mask);
  return result;
}

}  // namespace proxygi::ref
