// Image checks: each checkpoint's final frame over a region against its golden PNG (8-bit sRGB,
// what the frame is), or a linear AOV against its golden EXR (32-bit float: full precision).
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

Status attach_images(CheckContext& c, int frame, const image::ImageF* golden, const image::ImageF& actual,
                     const image::ImageF* diff, const image::ImageF* flip) {
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
  if (Status s = put("new", actual, images.actual); !s) return s;
  if (golden != nullptr)
    if (Status s = put("golden", *golden, images.golden); !s) return s;
  if (diff != nullptr)
    if (Status s = put("diff", *diff, images.diff); !s) return s;
  if (flip != nullptr && flip->width > 0)
    if (Status s = put("flip", *flip, images.flip); !s) return s;
  c.result.images = std::move(images);
  return {};
}

namespace {

// A golden: its comparable codes and its linear image (for the report).
struct GoldenImage {
  CodeImage codes;
  image::ImageF linear;
  std::string tier;
};

// The frame's golden: an AOV's EXR (a former 8-bit PNG golden of it still counts, with a note)
// or the final frame's PNG; nothing when absent.
Result<std::optional<GoldenImage>> read_golden(CheckContext& c, int frame, bool linear_aov) {
  const std::string exr = frame_file(frame, "exr"), png = frame_file(frame);
  std::optional<std::string> tier;
  std::string file = linear_aov ? exr : png;
  tier = c.store.find_tier(c.result.scenario, c.check.name, file);
  if (!tier && linear_aov) {
    tier = c.store.find_tier(c.result.scenario, c.check.name, png);
    if (tier) {
      file = png;
      c.result.details.push_back("frame " + std::to_string(frame) + ": golden is an 8-bit PNG; bless to store it as EXR");
    }
  }
  if (!tier) return std::optional<GoldenImage>();
  auto read = image::read_image(c.store.dir(c.result.scenario, *tier, c.check.name) / file);
  if (!read) return read.error();
  GoldenImage golden;
  golden.codes = file == exr ? codes_of(*read) : codes_of(from_png(*read));
  golden.linear = std::move(*read);
  golden.tier = *tier;
  return std::optional<GoldenImage>(std::move(golden));
}

}  // namespace

Status run_image_check(CheckContext& c) {
  const Check& check = c.check;
  CheckResult& result = c.result;
  const bool linear_aov = check.aov != Aov::final_frame;
  result.metric = "failing fraction";
  result.threshold = check.image.max_failing_fraction;
  int shown = -1;
  double worst = -1.0;
  std::optional<image::ImageF> shown_golden;
  image::ImageF shown_actual;
  ImageComparison shown_comparison;
  std::vector<int> missing;
  for (int frame : check.frames) {
    auto rendered = c.run.frame(frame);
    if (!rendered) return rendered.error();
    const CodeImage actual = linear_aov ? codes_of((*rendered)->aov(check.aov)) : codes_of((*rendered)->final_frame);
    auto actual_linear = [&] { return linear_aov ? (*rendered)->aov(check.aov) : to_linear((*rendered)->final_frame); };
    const std::vector<std::uint8_t> mask = region_mask((*rendered)->classes, check.region);
    auto golden = read_golden(c, frame, linear_aov);
    if (!golden) return golden.error();
    if (c.bless) {
      const auto path = c.store.bless_path(result.scenario, check.name, frame_file(frame, linear_aov ? "exr" : "png"));
      std::error_code error;
      std::filesystem::create_directories(path.parent_path(), error);
      if (Status s = linear_aov ? image::write_exr(path, (*rendered)->aov(check.aov)) : image::write_png(path, actual_linear()); !s)
        return s;
      // The EXR replaces a former 8-bit PNG golden of this AOV in the tier blessed.
      if (const auto png = c.store.bless_path(result.scenario, check.name, frame_file(frame)); linear_aov && std::filesystem::exists(png, error)) {
        std::filesystem::remove(png, error);
        if (error) return make_error(png.string() + ": " + error.message());
        result.details.push_back("frame " + std::to_string(frame) + ": removed the former PNG golden " + png.generic_string());
      }
      if (!*golden) {
        result.details.push_back("frame " + std::to_string(frame) + ": new golden " + path.generic_string());
      } else if (auto d = compare_images(actual, (*golden)->codes, mask, {0, 0.0}); d.ok()) {
        result.details.push_back("frame " + std::to_string(frame) + ": " +
                                 (d->failing == 0 ? std::string("unchanged") : "changed: " + d->summary) +
                                 ((*golden)->tier != c.store.family ? " (was the " + (*golden)->tier + " tier's)" : ""));
      }
      continue;
    }
    if (!*golden) {
      missing.push_back(frame);
      if (shown < 0) shown = frame, shown_actual = actual_linear();
      continue;
    }
    result.tier = (*golden)->tier;
    const double scale = result.tier == std::string(kFallbackTier) ? check.fallback_scale : 1.0;
    result.threshold = check.image.max_failing_fraction * scale;
    auto comparison = compare_images(actual, (*golden)->codes, mask, check.image, scale);
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
      shown_golden = std::move((*golden)->linear);
      shown_actual = actual_linear();
      shown_comparison = std::move(*comparison);
    }
  }
  if (c.bless) {
    result.outcome = Outcome::blessed;
    result.message = "blessed " + std::to_string(check.frames.size()) + " frames into the " + c.store.family + " tier" +
                     (linear_aov ? " (EXR)" : "");
    return {};
  }
  if (!missing.empty()) {
    result.outcome = Outcome::new_golden;
    result.message = "no golden for " + std::to_string(missing.size()) + " frame(s) (first " + std::to_string(missing[0]) +
                     ", device family " + c.store.family + ")";
    return attach_images(c, shown, nullptr, shown_actual, nullptr, nullptr);
  }
  result.outcome = result.first_failing_frame >= 0 ? Outcome::fail : Outcome::pass;
  // A failure's message is its first failing frame's line (not a PNG-golden note before it).
  std::string first_failure;
  for (const std::string& d : result.details)
    if (d.rfind("frame " + std::to_string(result.first_failing_frame) + ": ", 0) == 0 && d.find("8-bit PNG") == std::string::npos) {
      first_failure = d;
      break;
    }
  result.message = result.first_failing_frame >= 0
                       ? "frame " + std::to_string(result.first_failing_frame) + ": " + first_failure.substr(first_failure.find(": ") + 2)
                       : "worst frame " + std::to_string(shown) + ": " + shown_comparison.summary;
  return attach_images(c, shown, &*shown_golden, shown_actual, &shown_comparison.diff, &shown_comparison.flip);
}

}  // namespace proxygi::regress
