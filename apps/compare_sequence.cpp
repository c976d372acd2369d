#include "apps/compare_sequence.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/scene_input.h"
#include "image/image.h"
#include "run/frame_plan.h"
#include "study/sequence_temporal.h"

namespace proxygi::app {
namespace {

std::string frame_file(const std::string& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.exr", frame);
  return (std::filesystem::path(dir) / name).string();
}

Result<ref::Plane> luminance_of(const std::string& path) {
  auto image = image::read_image(path);
  if (!image) return image.error();
  ref::Plane plane(image->width, image->height);
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x) plane.at(x, y) = image::rec709_luminance<float>(image->at(x, y));
  return plane;
}

nlohmann::json summary_json(const study::ErrorSummary& e) { return {{"mean", e.mean}, {"max", e.max}, {"pixels", e.pixels}}; }
nlohmann::json flicker_json(const study::FlickerSummary& f) {
  return {{"mean", f.mean}, {"p99", f.p99}, {"max", f.max}, {"points", f.points}};
}
nlohmann::json scores_json(const study::TemporalScores& s) {
  return {{"temporal_gradient_error", summary_json(s.gradient)}, {"pop", summary_json(s.pop)},
          {"flicker_test", flicker_json(s.flicker_test)}, {"flicker_reference", flicker_json(s.flicker_reference)},
          {"flicker_error", flicker_json(s.flicker_error)}, {"reference_mean_luminance", s.reference_mean}};
}

}  // namespace

int run_compare_sequence(const SequenceCompareArgs& args) {
  auto range = run::parse_frame_range(args.frames);
  if (!range) return fail_bad_input("compare --sequence: --frames: " + range.message());
  auto loaded = open_scene(SceneArgs{args.scene, "", 0, ""});
  if (!loaded) return fail_bad_input(loaded.message());
  std::vector<ref::Plane> test, reference;
  for (int frame = range->first; frame <= range->last; ++frame) {
    for (auto [dir, planes] : {std::pair{&args.test_dir, &test}, std::pair{&args.reference_dir, &reference}}) {
      auto plane = luminance_of(frame_file(*dir, frame));
      if (!plane)
        return fail_bad_input("compare --sequence: " + plane.message() +
                              " (the frames are linear radiance: record --exr, or reference -o DIR/frame_NNNNN.exr per frame)");
      planes->push_back(std::move(*plane));
    }
    if (test.back().width != test.front().width || test.back().height != test.front().height ||
        reference.back().width != test.front().width || reference.back().height != test.front().height)
      return fail_bad_input("compare --sequence: frame " + std::to_string(frame) + ": " + frame_file(args.test_dir, frame) + " and " +
                            frame_file(args.reference_dir, frame) + " must both be " + std::to_string(test.front().width) + "x" +
                            std::to_string(test.front().height));
  }
  auto world = world::World::load(*loaded, {.assets_dir = assets_dir(), .load_rigs = false});
  if (!world) return fail_bad_input(world.message());
  const ref::SceneGeometry geometry = ref::make_scene_geometry(**world);
  auto traced = study::trace_sequence(**world, geometry, range->first, range->last, test.front().width, test.front().height);
  if (!traced) return fail_bad_input("compare --sequence: " + traced.message());
  auto scores = study::score_sequence(test, reference, *traced);
  if (!scores) return fail_bad_input("compare --sequence: " + scores.message());
  const nlohmann::json out = {{"test", args.test_dir},
                              {"reference", args.reference_dir},
                              {"frames", {range->first, range->last}},
                              {"width", test.front().width},
                              {"height", test.front().height},
                              {"regions",
                               {{"all", scores_json(scores->all)},
                                {"character", scores_json(scores->character)},
                                {"static_world", scores_json(scores->static_world)}}}};
  if (args.json) {
    std::printf("%s\n", out.dump(2).c_str());
    return kExitOk;
  }
  std::printf("frames %d:%d, %dx%d, luminance of linear radiance; exact reprojection traced from the scene\n", range->first, range->last,
              test.front().width, test.front().height);
  std::printf("%-13s %10s %22s %22s %30s\n", "region", "ref. mean", "E_delta mean / max", "pop mean / max", "flicker F test / ref / error");
  for (const auto& [name, s] : {std::pair{"all", &scores->all}, std::pair{"character", &scores->character},
                                std::pair{"static world", &scores->static_world}}) {
    std::printf("%-13s %10.4g %10.4g / %-10.4g %10.4g / %-10.4g ", name, s->reference_mean, s->gradient.mean, s->gradient.max, s->pop.mean,
                s->pop.max);
    if (s->flicker_test.points == 0) std::printf("%9s\n", "n/a (moves)");  // flicker is scored on the static world only
    else std::printf("%9.4g / %-9.4g / %-9.4g\n", s->flicker_test.mean, s->flicker_reference.mean, s->flicker_error.mean);
  }
  return kExitOk;
}

}  // namespace proxygi::app
