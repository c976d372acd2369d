#include "apps/compare_regions.h"

#include <cmath>
#include <cstdio>

#include "image/image.h"
#include "study/stability_metrics.h"

namespace proxygi::app {
namespace {

Result<image::ImageF> read_same_size(const std::string& path, const image::ImageF& test, const char* option) {
  auto read = image::read_image(path);
  if (!read) return make_error(std::string(option) + ": " + read.message());
  if (read->width != test.width || read->height != test.height)
    return make_error(std::string(option) + " " + path + ": size mismatch: " + std::to_string(read->width) + "x" +
                      std::to_string(read->height) + ", test is " + std::to_string(test.width) + "x" + std::to_string(test.height));
  return read;
}

ref::Plane luminance_plane(const image::ImageF& image) {
  ref::Plane plane(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4& p = image.at(x, y);
      plane.at(x, y) = image::rec709_luminance<float>(p);
    }
  return plane;
}

nlohmann::json region(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask& mask) {
  const std::size_t pixels = mask.count();
  if (pixels == 0) return {{"pixels", 0}, {"rmse", nullptr}, {"relative_mse", nullptr}};
  auto rmse = ref::rmse(test, reference, &mask);
  auto relative = ref::relative_mse(test, reference, &mask);
  return {{"pixels", pixels}, {"rmse", rmse ? nlohmann::json(rmse->mean) : nlohmann::json()},
          {"relative_mse", relative ? nlohmann::json(relative->mean) : nlohmann::json()}};
}

}  // namespace

Result<nlohmann::json> region_scores(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask* receivers,
                                     const RegionInputs& inputs) {
  const ref::ReceiverMask all = receivers != nullptr ? *receivers : ref::mask_where(test.width, test.height, [](int, int) { return true; });
  std::optional<image::ImageF> unshadowed;
  if (!inputs.unshadowed.empty()) {
    auto read = read_same_size(inputs.unshadowed, test, "--unshadowed");
    if (!read) return make_error(read.message());
    unshadowed = std::move(*read);
  }
  std::size_t negative = 0, non_finite = 0, over = 0;
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x) {
      if (!all.contains(std::size_t(y) * std::size_t(test.width) + std::size_t(x))) continue;
      const glm::vec4& p = test.at(x, y);
      bool finite = true, below = false, above = false;
      for (int c = 0; c < 3; ++c) {
        finite = finite && std::isfinite(p[c]);
        below = below || p[c] < 0.0f;
        if (unshadowed) above = above || p[c] > unshadowed->at(x, y)[c] * float(1.0 + study::kDisplayStep);
      }
      non_finite += finite ? 0 : 1;
      negative += finite && below ? 1 : 0;
      over += finite && above ? 1 : 0;
    }
  nlohmann::json out;
  out["bounds"] = {{"pixels", all.count()}, {"negative", negative}, {"non_finite", non_finite},
                   {"over_unshadowed", unshadowed ? nlohmann::json(over) : nlohmann::json()}};
  out["regions"] = nlohmann::json::object();
  if (unshadowed) {
    const ref::ReceiverMask shadow = study::mask_and(study::shadow_mask(luminance_plane(reference), luminance_plane(*unshadowed)), all);
    out["regions"]["shadow"] = region(test, reference, shadow);
  }
  if (!inputs.depth.empty()) {
    auto depth = read_same_size(inputs.depth, test, "--depth");
    if (!depth) return make_error(depth.message());
    const ref::ReceiverMask edge = study::mask_and(study::edge_band_mask(ref::channel_plane(*depth, 0), inputs.edge_radius), all);
    out["regions"]["edge_band"] = region(test, reference, edge);
    out["regions"]["interior"] = region(test, reference, study::mask_and_not(all, edge));
  }
  if (!inputs.character.empty()) {
    auto character = read_same_size(inputs.character, test, "--character");
    if (!character) return make_error(character.message());
    out["regions"]["character"] = region(test, reference, study::mask_and(ref::mask_from_image(*character), all));
  }
  return out;
}

std::string region_text(const nlohmann::json& scores) {
  std::string text;
  char line[256];
  const nlohmann::json& b = scores["bounds"];
  std::snprintf(line, sizeof line, "bounds     %zu negative, %zu NaN/Inf, %s above unshadowed + 1/255\n", b["negative"].get<std::size_t>(),
                b["non_finite"].get<std::size_t>(), b["over_unshadowed"].is_null() ? "n/a" : std::to_string(b["over_unshadowed"].get<std::size_t>()).c_str());
  text += line;
  for (const auto& [name, r] : scores["regions"].items()) {
    if (r["pixels"].get<std::size_t>() == 0) {
      std::snprintf(line, sizeof line, "%-10s no pixels\n", name.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-10s %zu pixels, RMSE %.6g, relMSE %.6g\n", name.c_str(), r["pixels"].get<std::size_t>(),
                    r["rmse"].get<double>(), r["relative_mse"].get<double>());
    }
    text += line;
  }
  return text;
}

}  // namespace proxygi::app
