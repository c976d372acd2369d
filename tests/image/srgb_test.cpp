#include <gtest/gtest.h>

#include <cmath>

#include "image/image.h"

namespace proxygi::image {
namespace {

// IEC 61966-2-1 in double precision, written out independently of srgb.cpp.
double iec_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double iec_encode(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

TEST(Srgb, MatchesTheStandardFormulaAcrossTheRange) {
  for (int i = 0; i <= 1000; ++i) {
    const double v = i / 1000.0;
    EXPECT_NEAR(srgb_to_linear(float(v)), iec_decode(v), 1e-6) << v;
    EXPECT_NEAR(linear_to_srgb(float(v)), iec_encode(v), 1e-6) << v;
  }
}

TEST(Srgb, KnownValues) {
  // Hand values: 0.5 -> ((0.555/1.055)^2.4) = 0.214041; 0.04045 sits on the linear segment:
  // 0.04045/12.92 = 0.0031308; linear 0.18 (mid grey) -> 1.055*0.18^(1/2.4) - 0.055 = 0.461356.
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.214041f, 1e-6f);
  EXPECT_NEAR(srgb_to_linear(0.04045f), 0.0031308f, 1e-7f);
  EXPECT_NEAR(linear_to_srgb(0.18f), 0.461356f, 1e-6f);
  EXPECT_EQ(srgb_to_linear(0.0f), 0.0f);
  EXPECT_NEAR(srgb_to_linear(1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(linear_to_srgb(1.0f), 1.0f, 1e-6f);
}

TEST(Srgb, RoundTripsEvery8BitCode) {
  for (int code = 0; code < 256; ++code) {
    const float encoded = float(code) / 255.0f;
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(encoded)), encoded, 1e-5f) << code;
  }
}

}  // namespace
}  // namespace proxygi::image
