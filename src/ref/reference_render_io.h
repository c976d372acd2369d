#pragma once
// Files of a reference render and the guided-filtered variant.
//
// For an output path OUT.exr (any name; the extension is replaced):
//   OUT.exr            linear RGBA float radiance, a = 1 (the method's image: guided-filtered
//                      when the filter is on, else the plain mean of all samples). Pixels that
//                      see the environment show its full radiance, as the rasterizer's HDR output.
//   OUT.unfiltered.exr only with the filter: the plain mean (what --accumulate resumes from).
//   OUT.indirect.exr   the part of the radiance that bounced at least once (mean), a = 1.
//   OUT.variance.exr   per channel variance of the mean radiance, s²/n, a = 1 (Z-tests).
//   OUT.albedo.exr     primary-hit albedo, a = mask.      (features: pixel-center ray)
//   OUT.normal.exr     world normal facing the camera, a = mask.
//   OUT.depth.exr      eye depth in meters in r, g, b (0 = no hit), a = mask.
//   OUT.mask.exr       rgb = 1 where the pixel center hits geometry, else 0; a = 1
//                      (`proxygi compare --mask OUT.mask.exr` reads it).
//   OUT.character.exr  rgb = 1 where the centers of the pixel and its 8 neighbours hit a
//                      character, else 0; a = 1 (the "character" region without its silhouette:
//                      `proxygi compare --mask OUT.character.exr`).
//   OUT.json           the record below: what was rendered, with how many samples.
//   OUT.partial        only while a run is unfinished (interrupted, e.g. Ctrl-C): the exact
//                      double sums of its whole samples, so that `--accumulate` continues them to
//                      the same bits an uninterrupted run gives. Removed when the run completes.
// Every file is written atomically.
#include <cstdint>
#include <filesystem>
#include <string>

#include "base/result.h"
#include "image/image.h"
#include "ref/reference_render.h"

namespace proxygi::ref {

struct ReferencePaths {
  std::filesystem::path radiance, unfiltered, indirect, variance, albedo, normal, depth, mask, character, record, partial;
};
ReferencePaths reference_paths(const std::filesystem::path& output);

// What a reference image is; a resumed run must match every field but samples and timing.
struct ReferenceRecord {
  std::string scene;      // the scene argument as given ("default" or a file path)
  int frame = 0;
  double time_s = 0.0;    // scene time of the frame
  int width = 0;
  int height = 0;
  std::string transport;  // "direct", "one-bounce", "multi-bounce"
  std::string lighting;   // "sh", "full"
  int sh_order = 0;       // the lighting order (--lighting-order; used when lighting is "sh")
  std::uint32_t seed = 0;
  std::string sampler = "sobol";  // ref::sampler_name; records without it were made by "random"
  std::uint32_t samples = 0;  // per pixel, all runs together
  std::uint32_t target_samples = 0;  // what the run was asked to reach; > samples while unfinished
  bool guided_filter = false;
  double seconds = 0.0;   // tracing time, all runs together
  std::uint64_t rays = 0; // all runs together
};

Result<ReferenceRecord> read_record(const std::filesystem::path& path);
// Empty when `previous` describes the same image as `current`, else what differs.
std::string record_mismatch(const ReferenceRecord& previous, const ReferenceRecord& current);

// The sums of a previous run: exactly from OUT.partial when it holds record.samples samples,
// else read back (to float precision) from its radiance (or unfiltered), indirect and variance
// EXRs and its record.
Result<SampleSums> read_previous_sums(const ReferencePaths& paths, const ReferenceRecord& record);

// OUT.partial: "proxygi-sums 1\n", then width, height, samples (uint32, little-endian as the
// machine), then per pixel radiance, radiance², indirect (9 doubles).
Status write_partial_sums(const std::filesystem::path& path, const SampleSums& sums);
Result<SampleSums> read_partial_sums(const std::filesystem::path& path);

struct GuidedFilterSettings {
  int radius = 24;
  float depth_scale = 20.0f;  // meters: a constant of the scene's extent (guided_filter.h)
};
// Bauszat's recipe: the indirect image is guided-filtered by normal and depth, the direct part
// (radiance - indirect) is kept, and they are summed on covered pixels; background pixels keep
// the environment radiance.
Result<image::ImageF> guided_filter_reference(const ReferenceImages& images, const PixelFeatures& features,
                                              const GuidedFilterSettings& settings);

// Writes every file listed above. `filtered` (may be null) becomes OUT.exr and the plain mean
// goes to OUT.unfiltered.exr.
Status write_reference(const ReferencePaths& paths, const ReferenceImages& images, const PixelFeatures& features,
                       const ReferenceRecord& record, const image::ImageF* filtered);

}  // namespace proxygi::ref
