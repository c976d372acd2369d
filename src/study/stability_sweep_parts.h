#pragma once
// Helpers the stability sweep files share (not a public contract of the study library).
#include <chrono>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "settings/render_settings.h"

#include "study/stability_shading.h"
#include "study/stability_sweeps.h"

namespace proxygi::study {

// The product's τ the sweeps run HYB at (the setting's default), and the ground receivers' normal.
inline const float kTau = settings::RenderSettings{}.hyb_tau;
inline const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

// A posed "character" of five spheres standing on the ground at the origin (S5, S7, S9).
std::vector<render::Sphere> five_sphere_character();

// Appends a point; it passes when finite and ≤ its metric's threshold.
void add_point(SweepResult& sweep, std::string method, std::string series, double x, int metric, double value);
// Counts the frame output's bounds (clamped value against its unshadowed shade) into sweep.bounds.
void count_output(SweepResult& sweep, const MethodShade& shade);
// |blocked light of the method − blocked light of the truth| / u: both measured from their own
// unshadowed shade, so the cube map's interpolation of LH does not count as shadow error.
double blocked_error_u(const MethodShade& shade, double truth_unshadowed, double truth_shadowed);
std::string fixed(double value, int digits);

template <class Sweep>
SweepResult timed(Sweep sweep, const StabilityOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SweepResult result = sweep(options);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace proxygi::study
