// proxygi compare TEST REFERENCE [--json] [--mask MASK.png] [--error-image OUT.png]
//   [--unshadowed IMAGE] [--depth IMAGE] [--edge-radius N] [--character IMAGE]: RMSE, relative MSE, SSIM and FLIP of a
// test image against a reference, and both images' mean luminance, over receiver pixels; bounds
// (negative, NaN/Inf, above unshadowed) and per-region scores (apps/compare_regions.h).
// Unreadable images, a size mismatch or an empty mask exit with code 2; a failed error-image
// write exits with code 1. With --sequence TEST and REFERENCE are folders of frames: the temporal
// metrics with exact reprojection (apps/compare_sequence.h).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/compare_regions.h"
#include "apps/compare_sequence.h"
#include "image/image.h"
#include "ref/error_image.h"
#include "ref/flip.h"
#include "ref/metrics.h"
#include "ref/ssim.h"

namespace proxygi::app {
namespace {

struct CompareArgs {
  std::string test;
  std::string reference;
  std::string mask;
  std::string error_image;
  std::string error_metric = "flip";
  std::string flip_mode = "auto";
  double pixels_per_degree = ref::kDefaultPixelsPerDegree;
  float error_scale = 0.0f;  // 0: 1 for FLIP, the map's maximum for RMSE
  bool json = false;
  RegionInputs regions;
};

bool is_high_dynamic_range_file(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".exr" || extension == ".hdr";
}

int run_compare(const CompareArgs& args) {
  auto test = image::read_image(args.test);
  if (!test) return fail_bad_input(test.message());
  auto reference = image::read_image(args.reference);
  if (!reference) return fail_bad_input(reference.message());
  std::optional<ref::ReceiverMask> mask;
  if (!args.mask.empty()) {
    auto mask_image = image::read_image(args.mask);
    if (!mask_image) return fail_bad_input(mask_image.message());
    mask = ref::mask_from_image(*mask_image);
  }
  const ref::ReceiverMask* receivers = mask ? &*mask : nullptr;
  if (Status ok = ref::check_comparable(*test, *reference, receivers); !ok)
    return fail_bad_input(args.test + " vs " + args.reference + ": " + ok.message());

  auto rmse = ref::rmse(*test, *reference, receivers);
  auto relative = ref::relative_mse(*test, *reference, receivers);
  if (!rmse || !relative) return fail_runtime(!rmse ? rmse.message() : relative.message());
  // SSIM needs an 11x11 window: smaller images report no SSIM instead of failing the comparison.
  auto ssim = ref::ssim(*test, *reference, receivers);
  const bool has_ssim = ssim.ok();
  const double ssim_mean = has_ssim ? ssim->mean : 0.0;

  if (is_high_dynamic_range_file(args.test) != is_high_dynamic_range_file(args.reference))
    std::fprintf(stderr,
                 "proxygi: warning: comparing a PNG (tonemapped, sRGB) with linear radiance (%s); the scores mix two "
                 "encodings: compare the record's .exr (--exr) with the reference's .exr instead\n",
                 is_high_dynamic_range_file(args.test) ? args.test.c_str() : args.reference.c_str());
  const bool hdr = args.flip_mode == "hdr" ||
                   (args.flip_mode == "auto" && (is_high_dynamic_range_file(args.test) || is_high_dynamic_range_file(args.reference)));
  ref::MetricResult flip;
  nlohmann::json exposures;
  if (hdr) {
    ref::HdrFlipOptions options;
    options.pixels_per_degree = args.pixels_per_degree;
    auto result = ref::flip_hdr(*test, *reference, receivers, options);
    if (!result) return fail_bad_input(result.message());
    exposures = {{"start", result->start_exposure}, {"stop", result->stop_exposure}, {"count", result->exposure_count}};
    flip = std::move(result->flip);
  } else {
    auto result = ref::flip_ldr(*test, *reference, receivers, ref::FlipOptions{args.pixels_per_degree});
    if (!result) return fail_bad_input(result.message());
    flip = std::move(*result);
  }

  if (!args.error_image.empty()) {
    const ref::Plane& map = args.error_metric == "flip" ? flip.map : rmse->map;
    float scale = args.error_scale;
    if (scale <= 0.0f) scale = args.error_metric == "flip" ? 1.0f : std::max(1e-12f, *std::max_element(map.values.begin(), map.values.end()));
    const std::vector<std::uint8_t>* drawn = receivers != nullptr ? &receivers->receiver : nullptr;
    if (Status written = ref::write_error_image(args.error_image, map, scale, drawn); !written)
      return fail_runtime(written.message());
  }

  auto regions = region_scores(*test, *reference, receivers, args.regions);
  if (!regions) return fail_bad_input(regions.message());

  nlohmann::json out = {
      {"test", args.test},
      {"reference", args.reference},
      {"width", test->width},
      {"height", test->height},
      {"receiver_pixels", rmse->pixels},
      {"rmse", rmse->mean},
      {"test_mean_luminance", ref::mean_luminance(*test, receivers)},
      {"reference_mean_luminance", ref::mean_luminance(*reference, receivers)},
      {"relative_mse", relative->mean},
      {"relative_mse_epsilon", ref::kRelativeMseEpsilon},
      {"ssim", has_ssim ? nlohmann::json(ssim_mean) : nlohmann::json()},
      {"flip", flip.mean},
      {"flip_mode", hdr ? "hdr" : "ldr"},
      {"pixels_per_degree", args.pixels_per_degree},
      {"flip_exposures", exposures},
      {"error_image", args.error_image.empty() ? nlohmann::json() : nlohmann::json(args.error_image)},
      {"bounds", (*regions)["bounds"]},
      {"regions", (*regions)["regions"]},
  };
  if (args.json) {
    std::printf("%s\n", out.dump(2).c_str());
    return kExitOk;
  }
  std::printf("test       %s\nreference  %s\n", args.test.c_str(), args.reference.c_str());
  std::printf("pixels     %zu receivers of %dx%d\n", rmse->pixels, test->width, test->height);
  const double test_mean = ref::mean_luminance(*test, receivers), reference_mean = ref::mean_luminance(*reference, receivers);
  std::printf("luminance  %.6g test, %.6g reference (ratio %.4f)\n", test_mean, reference_mean,
              reference_mean != 0.0 ? test_mean / reference_mean : 0.0);
  std::printf("RMSE       %.6g\n", rmse->mean);
  std::printf("relMSE     %.6g (epsilon %.g)\n", relative->mean, ref::kRelativeMseEpsilon);
  if (has_ssim) {
    std::printf("SSIM       %.6f\n", ssim_mean);
  } else {
    std::printf("SSIM       n/a (%s)\n", ssim.message().c_str());
  }
  if (hdr) {
    std::printf("FLIP       %.6f (HDR-FLIP, %.1f ppd, %d exposures from %.3f to %.3f stops)\n", flip.mean,
                args.pixels_per_degree, exposures["count"].get<int>(), exposures["start"].get<double>(),
                exposures["stop"].get<double>());
  } else {
    std::printf("FLIP       %.6f (LDR-FLIP, %.1f ppd)\n", flip.mean, args.pixels_per_degree);
  }
  if (!args.error_image.empty()) std::printf("error map  %s (%s)\n", args.error_image.c_str(), args.error_metric.c_str());
  std::printf("%s", region_text(*regions).c_str());
  return kExitOk;
}

}  // namespace

void add_compare_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("compare", "Compare two images: RMSE, relative MSE, SSIM, FLIP over receiver pixels");
  static CompareArgs args;
  command->add_option("test", args.test, "Image under test (EXR, PNG or HDR)")->required();
  command->add_option("reference", args.reference, "Reference image, same size (EXR, PNG or HDR)")->required();
  command->add_flag("--json", args.json, "Print one JSON object");
  command->add_option("--mask", args.mask, "Receiver mask image: white (max(r,g,b) * alpha > 0.5) pixels are averaged");
  command->add_option("--error-image", args.error_image, "Write a false-color error map (PNG)");
  command->add_option("--unshadowed", args.regions.unshadowed,
                      "The frame without proxies: bounds above it and the shadow region (reference < 99 % of it)");
  command->add_option("--depth", args.regions.depth, "Eye depth image (red channel, 0 = background): edge band and interior regions");
  command->add_option("--character", args.regions.character,
                      "Character region image (the reference's .character.exr, white = character): its region scores");
  command->add_option("--edge-radius", args.regions.edge_radius, "Edge band half-width in pixels (default 1)")->check(CLI::Range(0, 64));
  command->add_option("--error-metric", args.error_metric, "Map drawn by --error-image: flip (0..1) or rmse")
      ->check(CLI::IsMember({"flip", "rmse"}));
  command->add_option("--error-scale", args.error_scale,
                      "Value drawn at the top of the color ramp (default: 1 for flip, the maximum for rmse)");
  command->add_option("--flip-mode", args.flip_mode, "auto (HDR-FLIP when an input is .exr/.hdr), ldr or hdr")
      ->check(CLI::IsMember({"auto", "ldr", "hdr"}));
  command->add_option("--ppd", args.pixels_per_degree, "FLIP observer: pixels per degree of visual angle (default 67)")
      ->check(CLI::PositiveNumber);
  static bool sequence = false;
  static std::string frames, scene;
  command->add_flag("--sequence", sequence,
                    "TEST and REFERENCE are folders of frame_%05d.exr: temporal metrics (E_delta, pop, flicker) with exact "
                    "reprojection traced from --scene");
  command->add_option("--frames", frames, "With --sequence: the frames A:B (inclusive) to compare");
  command->add_option("--scene", scene, "With --sequence: the scene both sequences show (as record's SCENE; default: default)");
  add_quiet_flag(*command);
  command->callback([&runner] {
    if (sequence) {
      runner = [] {
        if (frames.empty()) return fail_bad_input("compare --sequence: --frames A:B is required");
        return run_compare_sequence({args.test, args.reference, frames, scene, args.json});
      };
      return;
    }
    runner = [] { return run_compare(args); };
  });
}

}  // namespace proxygi::app
