#pragma once
// Rendering a reference image: the path tracer run over every pixel, on all cores, with
// deterministic output.
//
// Per pixel (x, y) (framebuffer convention of scene/camera.h: y down, centers at +0.5), sample
// index s in [first_sample, first_sample + spp): SampleStream(seed, y * width + x, s, sampler); the first
// two numbers jitter the camera position uniformly inside the pixel, (x + u0, y + u1), the ray is
// scene::ray_through_pixel at that position, the rest drive the path. The image is traced in
// rounds, one sample index per round over every pixel; each pixel is computed by one thread per
// round and its samples are added to its sums in index order, so the image does not depend on
// the thread count or the tile order, and a run stopped after a round and continued from its
// sums (accumulate_samples) gives the same doubles as one uninterrupted run.
//
// Accumulation keeps double sums per pixel (radiance, radiance², indirect), so runs over
// disjoint sample ranges merge into the mean of all samples (resume, shards).
//
// Features come from the noise-free primary ray through the pixel center (as the rasterizer's
// G-buffer, no anti-aliasing): coverage mask, albedo, shading normal facing the camera (world
// space) and eye depth (distance along the camera's forward axis, meters; the rasterizer's
// definition).
#include <csignal>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "image/image.h"
#include "ref/path_tracer.h"
#include "scene/camera.h"

namespace proxygi::ref {

struct RenderJob {
  int width = 256;
  int height = 256;
  int spp = 16;                 // samples per pixel traced by this job (>= 1)
  std::uint32_t first_sample = 0;  // index of the first sample (resume: the samples already done)
  std::uint32_t seed = 0;
  Sampler sampler = Sampler::sobol;  // ref/sampling.h
  int threads = 0;              // 0: std::thread::hardware_concurrency()
  int tile_size = 16;           // pixels per tile edge
  // When set and it becomes non-zero (a SIGINT handler), tracing stops after the round in
  // progress: the sums hold whole samples only.
  const volatile std::sig_atomic_t* stop = nullptr;
};

// Per-pixel double sums of a range of samples.
struct SampleSums {
  int width = 0;
  int height = 0;
  std::uint32_t samples = 0;  // per pixel
  std::vector<glm::dvec3> radiance;
  std::vector<glm::dvec3> radiance_squared;
  std::vector<glm::dvec3> indirect;

  // Sums of both (disjoint sample ranges of the same image). Fails when sizes differ.
  Status merge(const SampleSums& other);
};

struct PixelFeatures {
  image::ImageF mask;    // rgb = a = 1 where the center ray hits geometry, else 0 (a = 1)
  image::ImageF albedo;  // rgb albedo, a = mask
  image::ImageF normal;  // rgb unit world normal facing the camera, a = mask
  image::ImageF depth;   // rgb = eye depth in meters (0 where no hit), a = mask
  // rgb = 1 where the center rays of the pixel and of its 8 neighbours hit a character mesh (the
  // "character" region: silhouette pixels, whose samples also see the background, are left out),
  // else 0; a = 1
  image::ImageF character;
};

struct RenderProgress {
  int tiles_done = 0;       // over all rounds of the job
  int tiles_total = 0;      // tiles per round x job.spp
  std::uint32_t samples_done = 0;  // whole rounds finished by this job
  double elapsed_s = 0.0;
  double eta_s = 0.0;       // linear extrapolation from the tiles done
  std::uint64_t rays = 0;   // traced so far
};
using ProgressCallback = std::function<void(const RenderProgress&)>;

struct RenderStats {
  std::uint64_t rays = 0;
  double seconds = 0.0;
  double mrays_per_second() const { return seconds > 0.0 ? double(rays) / seconds * 1e-6 : 0.0; }
};

// Traces job.spp samples per pixel. `progress` (optional) is called from the calling thread
// about every `progress_interval_s`, after every round and once at the end. Fails on an invalid
// job. A stopped job (job.stop) returns the whole samples it finished (SampleSums::samples).
Result<SampleSums> render_samples(const PathTracer& tracer, const scene::CameraState& camera, const RenderJob& job,
                                  RenderStats* stats = nullptr, const ProgressCallback& progress = {},
                                  double progress_interval_s = 1.0);

// Adds sample indices job.first_sample .. job.first_sample + job.spp - 1 to `sums`, which must be
// job.width x job.height and hold the samples before job.first_sample (zeros for none). Stops
// early, after a whole round, when *job.stop becomes non-zero; sums.samples counts what was added.
Status accumulate_samples(const PathTracer& tracer, const scene::CameraState& camera, const RenderJob& job,
                          SampleSums& sums, RenderStats* stats = nullptr, const ProgressCallback& progress = {},
                          double progress_interval_s = 1.0);

PixelFeatures render_features(const EmbreeScene& scene, const scene::CameraState& camera, int width, int height);

struct ReferenceImages {
  image::ImageF radiance;  // mean radiance, rgb; a = 1
  image::ImageF indirect;  // mean of the indirect part, rgb; a = 1
  image::ImageF variance;  // per channel variance of the mean radiance, s² / n (0 when n < 2); a = 1
};
ReferenceImages to_images(const SampleSums& sums);
// Inverse of to_images for resuming: sums that reproduce those means and variances.
Result<SampleSums> from_images(const ReferenceImages& images, std::uint32_t samples);

}  // namespace proxygi::ref
