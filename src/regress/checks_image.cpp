// Image checks: each checkpoint's final frame or AOV over a region against its golden PNG.
#include <cstdio>

#include "base/atomic_file.h"
#include "regress/checks.h"
#include "regress/data_uri.h"
#include "regress/image_compare.h"

namespace proxygi::regress {
namespace {

Result<std::string> write_png_uri(const std::filesystem::path& path, const image::ImageF& image) {
  if (Status s = image::write_png(path, image); !s) return s.error();
  auto bytes = read_file(path, 64u << 20);
  if (!bytes) return bytes.error();
  return png_data_uri(*bytes);
}

}  // namespace

Result<std::optional<std::string>> read_text(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::optional<std::string>();
  auto bytes = read_file(path, 256u << 20);
  if (!bytes) return bytes.error();
  return std::optional<std::string>(std::string(bytes->begin(), bytes->end()));
}

Status attach_images(CheckContext& c, int frame, const Rgba8* golden, const Rgba8& actual, const image::ImageF* diff,
                     const image::ImageF* flip) {
  if (!c.options.report_dir) return {};
  const std::filesystem::path dir = *c.options.report_dir / c.result.scenario / c.result.check;
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) return make_error(dir.string() + ": " + error.message());
  const std::string stem = frame_file(frame, "");
  CheckImages images;
  images.frame = frame;
  auto put = [&](const char* kind, const image::ImageF& image, std::string& uri) -> Status {
    auto written = write_png_uri(dir / (stem.substr(0, stem.size() - 1) + "_" + kind + ".png"), image);
    if (!written) return written.error();
    uri = *written;
    return {};
  };
  if (Status s = put("new", to_linear(actual), images.actual); !s) return s;
  if (golden != nullptr)
    if (Status s = put("golden", to_linear(*golden), images.golden); !s) return s;
  if (diff != nullptr)
    if (Status s = put("diff", *diff, images.diff); !s) return s;
  if (flip != nullptr && flip->width > 0)
    if (Status s = put("flip", *flip, images.flip); !s) return s;
  c.result.images = std::move(images);
  return {};
}

Status run_image_check(CheckContext& c) {
  const Check& check = c.check;
  CheckResult& result = c.result;
  result.metric = "failing fraction";
  result.threshold = check.image.max_failing_fraction;
  int shown = -1;
  double worst = -1.0;
  std::optional<Rgba8> shown_golden;
  Rgba8 shown_actual;
  ImageComparison shown_comparison;
  std::vector<int> missing;
  for (int frame : check.frames) {
    auto rendered = c.run.frame(frame);
    if (!rendered) return rendered.error();
    const Rgba8& actual = (*rendered)->image(check.aov);
    const std::vector<std::uint8_t> mask = region_mask((*rendered)->classes, check.region);
    const std::string file = frame_file(frame);
    const auto tier = c.store.find_tier(result.scenario, check.name, file);
    std::optional<Rgba8> golden;
    if (tier) {
      auto read = image::read_image(c.store.dir(result.scenario, *tier, check.name) / file);
      if (!read) return read.error();
      golden = from_png(*read);
    }
    if (c.bless) {
      const auto path = c.store.bless_path(result.scenario, check.name, file);
      std::error_code error;
      std::filesystem::create_directories(path.parent_path(), error);
      if (Status s = image::write_png(path, to_linear(actual)); !s) return s;
      if (!golden) {
        result.details.push_back("frame " + std::to_string(frame) + ": new golden " + path.generic_string());
      } else if (auto d = compare_images(actual, *golden, mask, {0, 0.0}); d.ok()) {
        result.details.push_back("frame " + std::to_string(frame) + ": " +
                                 (d->failing == 0 ? std::string("unchanged") : "changed: " + d->summary) +
                                 (*tier != c.store.family ? " (was the " + *tier + " tier's)" : ""));
      }
      continue;
    }
    if (!golden) {
      missing.push_back(frame);
      if (shown < 0) shown = frame, shown_actual = actual;
      continue;
    }
    result.tier = *tier;
    const double scale = *tier == std::string(kFallbackTier) ? check.fallback_scale : 1.0;
    result.threshold = check.image.max_failing_fraction * scale;
    auto comparison = compare_images(actual, *golden, mask, check.image, scale);
    if (!comparison) return make_error("frame " + std::to_string(frame) + ": " + comparison.message());
    result.series.push_back({frame, comparison->failing_fraction, !comparison->passed});
    if (!comparison->passed) {
      result.details.push_back("frame " + std::to_string(frame) + ": " + comparison->summary);
      if (result.first_failing_frame < 0) result.first_failing_frame = frame;
    }
    const double badness = comparison->passed ? comparison->failing_fraction : 1e9 - frame;
    if (badness > worst) {
      worst = badness;
      shown = frame;
      shown_golden = golden;
      shown_actual = actual;
      shown_comparison = std::move(*comparison);
    }
  }
  if (c.bless) {
    result.outcome = Outcome::blessed;
    result.message = "blessed " + std::to_string(check.frames.size()) + " frames into the " + c.store.family + " tier";
    return {};
  }
  if (!missing.empty()) {
    result.outcome = Outcome::new_golden;
    result.message = "no golden for " + std::to_string(missing.size()) + " frame(s) (first " + std::to_string(missing[0]) +
                     ", device family " + c.store.family + ")";
    return attach_images(c, shown, nullptr, shown_actual, nullptr, nullptr);
  }
  result.outcome = result.first_failing_frame >= 0 ? Outcome::fail : Outcome::pass;
  result.message = result.first_failing_frame >= 0
                       ? "frame " + std::to_string(result.first_failing_frame) + ": " + result.details.front().substr(result.details.front().find(": ") + 2)
                       : "worst frame " + std::to_string(shown) + ": " + shown_comparison.summary;
  return attach_images(c, shown, &*shown_golden, shown_actual, &shown_comparison.diff, &shown_comparison.flip);
}

}  // namespace proxygi::regress
