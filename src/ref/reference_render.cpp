#include "ref/reference_render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace proxygi::ref {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height, int size) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += size)
    for (int x = 0; x < width; x += size) tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
  return tiles;
}

// Adds sample index `sample` of every pixel of the tile to its sums (one round).
void render_tile(const PathTracer& tracer, const scene::CameraState& camera, const RenderJob& job, std::uint32_t sample,
                 const Tile& tile, SampleSums& sums, std::uint64_t& rays) {
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const std::uint32_t pixel = std::uint32_t(y) * std::uint32_t(job.width) + std::uint32_t(x);
      SampleStream random(job.seed, pixel, sample, job.sampler);
      const glm::vec2 jitter = random.next_2d();
      const scene::Ray ray = scene::ray_through_pixel(camera, job.width, job.height, float(x) + jitter.x,
                                                      float(y) + jitter.y);
      const PathSample path = tracer.trace(ray, random);
      const glm::dvec3 value(path.radiance);
      sums.radiance[pixel] += value;
      sums.radiance_squared[pixel] += value * value;
      sums.indirect[pixel] += glm::dvec3(path.indirect);
      rays += path.rays;
    }
}

Status check_job(const RenderJob& job) {
  if (job.width < 1 || job.height < 1) return make_error("render: image size must be at least 1x1");
  if (job.spp < 1) return make_error("render: spp must be at least 1");
  if (job.tile_size < 1) return make_error("render: tile size must be at least 1");
  const std::size_t pixels = std::size_t(job.width) * std::size_t(job.height);
  if (pixels > (std::size_t(1) << 32)) return make_error("render: image too large for 32-bit pixel indices");
  return {};
}

bool stopped(const RenderJob& job) { return job.stop != nullptr && *job.stop != 0; }

}  // namespace

Status SampleSums::merge(const SampleSums& other) {
  if (other.width != width || other.height != height)
    return make_error("cannot merge sample sums of " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                      " into " + std::to_string(width) + "x" + std::to_string(height));
  for (std::size_t i = 0; i < radiance.size(); ++i) {
    radiance[i] += other.radiance[i];
    radiance_squared[i] += other.radiance_squared[i];
    indirect[i] += other.indirect[i];
  }
  samples += other.samples;
  return {};
}

Status accumulate_samples(const PathTracer& tracer, const scene::CameraState& camera, const RenderJob& job,
                          SampleSums& sums, RenderStats* stats, const ProgressCallback& progress, double progress_interval_s) {
  if (Status valid = check_job(job); !valid) return valid;
  const std::size_t pixels = std::size_t(job.width) * std::size_t(job.height);
  if (sums.width != job.width || sums.height != job.height || sums.radiance.size() != pixels ||
      sums.radiance_squared.size() != pixels || sums.indirect.size() != pixels)
    return make_error("render: the sums to accumulate into are " + std::to_string(sums.width) + "x" +
                      std::to_string(sums.height) + ", the job is " + std::to_string(job.width) + "x" +
                      std::to_string(job.height));

  const std::vector<Tile> tiles = make_tiles(job.width, job.height, job.tile_size);
  const int tiles_per_round = int(tiles.size());
  const int thread_count = std::max(1, job.threads > 0 ? job.threads : int(std::thread::hardware_concurrency()));
  std::atomic<std::uint64_t> total_rays{0};
  const Clock::time_point start = Clock::now();
  std::uint32_t rounds_done = 0;
  auto report = [&](int tiles_done) {
    if (!progress) return;
    RenderProgress p;
    p.tiles_done = tiles_done;
    p.tiles_total = tiles_per_round * job.spp;
    p.samples_done = rounds_done;
    p.elapsed_s = seconds_since(start);
    p.eta_s = tiles_done > 0 ? p.elapsed_s * double(p.tiles_total - tiles_done) / double(tiles_done) : 0.0;
    p.rays = total_rays.load();
    progress(p);
  };

  Clock::time_point last_report = start;
  for (int round = 0; round < job.spp && !stopped(job); ++round) {
    const std::uint32_t sample = job.first_sample + std::uint32_t(round);
    std::atomic<std::size_t> next_tile{0};
    std::mutex mutex;
    std::condition_variable tile_finished;
    int tiles_done = 0;
    auto worker = [&] {
      for (std::size_t t = next_tile++; t < tiles.size(); t = next_tile++) {
        std::uint64_t rays = 0;
        render_tile(tracer, camera, job, sample, tiles[t], sums, rays);
        total_rays += rays;
        {
          const std::lock_guard<std::mutex> lock(mutex);
          ++tiles_done;
        }
        tile_finished.notify_one();
      }
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < std::min(thread_count, tiles_per_round); ++i) threads.emplace_back(worker);
    {
      std::unique_lock<std::mutex> lock(mutex);
      while (tiles_done < tiles_per_round) {
        tile_finished.wait_for(lock, std::chrono::milliseconds(100));
        if (seconds_since(last_report) >= progress_interval_s && tiles_done < tiles_per_round) {
          const int done = round * tiles_per_round + tiles_done;
          lock.unlock();
          report(done);
          lock.lock();
          last_report = Clock::now();
        }
      }
    }
    for (std::thread& thread : threads) thread.join();
    ++rounds_done;
    ++sums.samples;
    report((round + 1) * tiles_per_round);
    last_report = Clock::now();
  }
  if (stats) {
    stats->rays = total_rays.load();
    stats->seconds = seconds_since(start);
  }
  return {};
}

Result<SampleSums> render_samples(const PathTracer& tracer, const scene::CameraState& camera, const RenderJob& job,
                                  RenderStats* stats, const ProgressCallback& progress, double progress_interval_s) {
  if (Status valid = check_job(job); !valid) return valid.error();
  SampleSums sums;
  sums.width = job.width;
  sums.height = job.height;
  const std::size_t pixels = std::size_t(job.width) * std::size_t(job.height);
  sums.radiance.assign(pixels, glm::dvec3(0.0));
  sums.radiance_squared.assign(pixels, glm::dvec3(0.0));
  sums.indirect.assign(pixels, glm::dvec3(0.0));
  if (Status s = accumulate_samples(tracer, camera, job, sums, stats, progress, progress_interval_s); !s) return s.error();
  return sums;
}

PixelFeatures render_features(const EmbreeScene& scene, const scene::CameraState& camera, int width, int height) {
  PixelFeatures out;
  out.mask = image::ImageF(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  out.albedo = image::ImageF(width, height);
  out.normal = image::ImageF(width, height);
  out.depth = image::ImageF(width, height);
  out.character = out.mask;
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const scene::Ray ray = scene::ray_through_pixel(camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
      const std::optional<SurfaceHit> hit = scene.intersect(ray.origin, ray.direction);
      if (!hit) continue;
      const float depth = glm::dot(hit->position - camera.eye, forward);
      out.mask.at(x, y) = glm::vec4(1.0f);
      out.albedo.at(x, y) = glm::vec4(hit->albedo, 1.0f);
      out.normal.at(x, y) = glm::vec4(hit->shading_normal, 1.0f);
      out.depth.at(x, y) = glm::vec4(depth, depth, depth, 1.0f);
      if (hit->character) out.character.at(x, y) = glm::vec4(1.0f);
    }
  // The region keeps only pixels whose 8 neighbours' centres hit the character too: a silhouette
  // pixel's jittered samples also see what lies behind (at 256² the default mannequin's mean
  // radiance over all its centre-hit pixels is 1.7× higher on a white ground than a black one).
  image::ImageF interior = out.character;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (out.character.at(x, y).r == 0.0f) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height || out.character.at(nx, ny).r == 0.0f)
            interior.at(x, y) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        }
    }
  out.character = std::move(interior);
  return out;
}

ReferenceImages to_images(const SampleSums& sums) {
  ReferenceImages out;
  out.radiance = image::ImageF(sums.width, sums.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  out.indirect = out.radiance;
  out.variance = out.radiance;
  if (sums.samples == 0) return out;
  const double n = double(sums.samples);
  for (std::size_t i = 0; i < sums.radiance.size(); ++i) {
    const glm::dvec3 mean = sums.radiance[i] / n;
    glm::dvec3 variance(0.0);
    if (sums.samples > 1)
      variance = glm::max((sums.radiance_squared[i] - n * mean * mean) / (n - 1.0), glm::dvec3(0.0)) / n;
    out.radiance.pixels[i] = glm::vec4(glm::vec3(mean), 1.0f);
    out.indirect.pixels[i] = glm::vec4(glm::vec3(sums.indirect[i] / n), 1.0f);
    out.variance.pixels[i] = glm::vec4(glm::vec3(variance), 1.0f);
  }
  return out;
}

Result<SampleSums> from_images(const ReferenceImages& images, std::uint32_t samples) {
  const int w = images.radiance.width, h = images.radiance.height;
  if (images.indirect.width != w || images.indirect.height != h || images.variance.width != w ||
      images.variance.height != h)
    return make_error("resume: radiance, indirect and variance images differ in size");
  if (samples == 0) return make_error("resume: the previous run has no samples");
  SampleSums sums;
  sums.width = w;
  sums.height = h;
  sums.samples = samples;
  const double n = double(samples);
  const std::size_t pixels = std::size_t(w) * std::size_t(h);
  sums.radiance.resize(pixels);
  sums.radiance_squared.resize(pixels);
  sums.indirect.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const glm::dvec3 mean(glm::vec3(images.radiance.pixels[i]));
    const glm::dvec3 variance(glm::vec3(images.variance.pixels[i]));
    sums.radiance[i] = mean * n;
    // Inverse of variance = (sum² - n mean²) / (n - 1) / n.
    sums.radiance_squared[i] = variance * n * (n - 1.0) + n * mean * mean;
    sums.indirect[i] = glm::dvec3(glm::vec3(images.indirect.pixels[i])) * n;
  }
  return sums;
}

}  // namespace proxygi::ref
