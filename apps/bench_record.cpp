// proxygi bench record [--frames N] [--repeats R] [--size S] [--levels 1,2,...] [--scene default|crowd]:
// `record`'s frame rate against `bench frame`'s for the same frames, measured in one run. Each
// repeat times, back to back on one renderer:
//   frame   run::time_pipelined_frames, what `bench frame` reports (two in flight, LDR + HDR
//           read back, nothing written);
//   stb     record's path with the PNG encoder used until 2026-12 (stb_image_write, level 8,
//           five filters tried per row): LDR read back, PNG encoded and written on run::TaskQueue
//           worker threads while the GPU renders on (cmd_record.cpp's render_in_flight);
//   png L   the same with libpng at zlib level L (image::encode_png_rgba8; kPngZlibLevel is
//           what `record` uses).
// It prints fps, the ratio frame-rate(frame) / frame-rate(variant) per repeat and its spread,
// the mean file size and the single-thread encode time of one frame per encoder.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "settings/limits.h"
#include "base/atomic_file.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "run/frame_loop.h"
#include "run/task_queue.h"
#include "scene/scene_defaults.h"

namespace proxygi::app {
namespace {

struct RecordBenchOptions {
  int frames = 24;
  int repeats = 3;
  int size = 512;
  std::vector<int> levels = {1, image::kPngZlibLevel, 6};
  std::string scene = "default";
  std::string device;
};

struct Variant {
  std::string name;
  bool record = false;  // false: time_pipelined_frames
  image::PngEncoder encoder = image::PngEncoder::libpng;
  int level = 0;
};

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// record's loop (cmd_record.cpp render_in_flight) with the encoder chosen; ms per frame, wall.
Result<double> time_record_path(gpu::SceneRenderer& renderer, const std::vector<int>& frames, const Variant& variant,
                                const std::filesystem::path& dir, std::size_t& bytes) {
  run::FrameLoopOptions options;
  options.output = gpu::FrameOutput::readback(false);  // no EXR: no HDR readback, as record
  options.output.float_targets = false;
  const std::size_t encoders = run::default_encoder_threads();
  const int width = int(renderer.config().width), height = int(renderer.config().height);
  std::vector<std::size_t> sizes(frames.size(), 0);
  const auto start = Clock::now();
  Status written;
  {
    run::TaskQueue writer(encoders, 2 * encoders);
    std::size_t index = 0;
    const Status rendered = run::render_frames(renderer, frames, options, [&](gpu::FinishedFrame& finished) -> Status {
      return writer.push([&, slot = index++, frame = finished.frame, ldr = std::move(finished.ldr)]() -> Status {
        auto encoded = image::encode_png_rgba8(ldr, width, height, variant.encoder, variant.level);
        if (!encoded) return encoded.error();
        sizes[slot] = encoded->size();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", frame);
        return write_file_atomically(dir / name, *encoded);
      });
    });
    written = writer.wait();
    if (!rendered) return rendered.error();
  }
  if (!written) return written.error();
  const double ms = ms_since(start) / double(frames.size());
  bytes = 0;
  for (std::size_t s : sizes) bytes += s;
  bytes /= std::max<std::size_t>(1, sizes.size());
  return ms;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

int run_bench_record(const RecordBenchOptions& options) {
  auto context = gpu::Context::create({.device_request = options.device});
  if (!context) return fail_runtime(context.message());
  scene::Scene scene = options.scene == "crowd" ? scene::crowd_scene() : scene::default_scene();
  scene.output.width = scene.output.height = options.size;
  auto renderer = gpu::SceneRenderer::create(**context, scene, {assets_dir(), true});
  if (!renderer) return fail_runtime(renderer.message());
  const int first = scene.output.first_frame;
  std::vector<int> frames;
  for (int i = 0; i < options.frames; ++i) frames.push_back(first + 2 + i);

  std::vector<Variant> variants = {{"frame", false}, {"stb", true, image::PngEncoder::stb, 8}};
  for (int level : options.levels)
    variants.push_back({"png " + std::to_string(level), true, image::PngEncoder::libpng, level});

  std::error_code error;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "proxygi-bench-record";
  std::filesystem::create_directories(dir, error);
  if (error) return fail_runtime(dir.string() + ": " + error.message());

  // Single-thread encode time and size of one rendered frame per encoder.
  std::vector<std::uint8_t> sample;
  {
    run::FrameLoopOptions loop;
    loop.output = gpu::FrameOutput::readback(false);
    const int one[] = {first + 2};
    if (Status s = run::render_frames(**renderer, one, loop, [&](gpu::FinishedFrame& f) {
          sample = std::move(f.ldr);
          return Status{};
        });
        !s)
      return fail_runtime(s.message());
  }
  const auto& report = (*context)->report();
  std::printf("device: %s (%s), %s scene, %dx%d, %d frames per variant, %d repeats, %zu encoder threads\n",
              report.name.c_str(), report.driver.c_str(), options.scene.c_str(), options.size, options.size,
              options.frames, options.repeats, run::default_encoder_threads());
  std::printf("encode one frame, one thread (mean of 5):\n");
  for (const Variant& variant : variants) {
    if (!variant.record) continue;
    const auto start = Clock::now();
    std::size_t size = 0;
    for (int i = 0; i < 5; ++i) {
      auto encoded = image::encode_png_rgba8(sample, options.size, options.size, variant.encoder, variant.level);
      if (!encoded) return fail_runtime(encoded.message());
      size = encoded->size();
    }
    std::printf("  %-6s %7.2f ms  %8zu bytes\n", variant.name.c_str(), ms_since(start) / 5.0, size);
  }

  std::map<std::string, std::vector<double>> ms, ratio;
  std::map<std::string, std::size_t> sizes;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    double frame_ms = 0.0;
    std::printf("repeat %d:", repeat + 1);
    for (const Variant& variant : variants) {
      double t = 0.0;
      if (!variant.record) {
        auto timed = run::time_pipelined_frames(**renderer, first, options.frames);
        if (!timed) return fail_runtime(timed.message());
        t = frame_ms = *timed;
      } else {
        auto timed = time_record_path(**renderer, frames, variant, dir, sizes[variant.name]);
        if (!timed) return fail_runtime(timed.message());
        t = *timed;
      }
      ms[variant.name].push_back(t);
      ratio[variant.name].push_back(t / frame_ms);
      std::printf("  %s %.1f fps (%.2fx)", variant.name.c_str(), 1000.0 / t, t / frame_ms);
    }
    std::printf("\n");
  }
  std::printf("%-6s %9s %9s  %s\n", "variant", "fps med", "bytes", "frame-rate ratio bench frame / variant: median [min, max]");
  for (const Variant& variant : variants) {
    const auto& r = ratio[variant.name];
    std::printf("%-7s %9.1f %9zu  %.2f [%.2f, %.2f]\n", variant.name.c_str(), 1000.0 / median(ms[variant.name]),
                sizes[variant.name], median(r), *std::min_element(r.begin(), r.end()),
                *std::max_element(r.begin(), r.end()));
  }
  std::filesystem::remove_all(dir, error);
  return kExitOk;
}

}  // namespace

void add_bench_record_command(CLI::App& bench, CommandRunner& runner) {
  auto options = std::make_shared<RecordBenchOptions>();
  auto* command = bench.add_subcommand(
      "record", "record's frame rate against bench frame's in one run, per PNG encoder and zlib level");
  command->add_option("--frames", options->frames, "Frames per variant and repeat")->check(CLI::Range(2, 1000));
  command->add_option("--repeats", options->repeats, "Interleaved repeats")->check(CLI::Range(1, 100));
  command->add_option("--size", options->size, "Square output size")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--levels", options->levels, "libpng zlib levels to measure")->delimiter(',');
  command->add_option("--scene", options->scene, "Built-in scene")->check(CLI::IsMember({"default", "crowd"}));
  add_device_option(*command, options->device);
  add_quiet_flag(*command);
  command->callback([&runner, options] { runner = [options] { return run_bench_record(*options); }; });
}

}  // namespace proxygi::app
