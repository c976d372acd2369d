#pragma once
// False-color pictures of per-pixel error maps, for people: a magma-like ramp (black -> purple ->
// orange -> pale yellow, perceptually ordered, readable in grayscale print) from 0 at the low
// end to `max_value` at the top. Values are clamped; NaN shows as the top color.
#include <filesystem>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics_plane.h"

namespace proxygi::ref {

// Linear RGB color of t in [0, 1] on the ramp (alpha 1).
glm::vec4 error_ramp(float t);

// Maps map values v to error_ramp(v / max_value). Pixels where `mask` is given and false are
// drawn mid-gray so ignored pixels do not read as "no error". max_value must be > 0.
image::ImageF false_color(const Plane& map, float max_value, const std::vector<std::uint8_t>* mask = nullptr);

// false_color written as an 8-bit sRGB PNG (atomically).
Status write_error_image(const std::filesystem::path& path, const Plane& map, float max_value,
                         const std::vector<std::uint8_t>* mask = nullptr);

}  // namespace proxygi::ref
