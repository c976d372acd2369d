#include "study/reference_study.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <unordered_map>

#include "ref/embree_scene.h"
#include "ref/flip.h"
#include "ref/path_tracer.h"
#include "ref/reference_render_io.h"
#include "ref/ssim.h"
#include "scene/camera.h"
#include "study/chart_regions.h"
#include "study/stability_metrics.h"

namespace proxygi::study {

namespace {

// Character vertices bucketed into cubes of kContactRadiusM: a point's neighbours within the
// radius lie in the 27 cubes around its own.
class VertexGrid {
 public:
  void add(const glm::vec3& p) { cells_[key(cell(p))].push_back(p); }
  bool near(const glm::vec3& p, float radius) const {
    const glm::ivec3 c = cell(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto found = cells_.find(key(c + glm::ivec3(dx, dy, dz)));
          if (found == cells_.end()) continue;
          for (const glm::vec3& q : found->second)
            if (glm::dot(q - p, q - p) <= radius * radius) return true;
        }
    return false;
  }

 private:
  static glm::ivec3 cell(const glm::vec3& p) { return glm::ivec3(glm::floor(p / kContactRadiusM)); }
  static std::int64_t key(const glm::ivec3& c) {
    return (std::int64_t(c.x & 0x1fffff) << 42) | (std::int64_t(c.y & 0x1fffff) << 21) | std::int64_t(c.z & 0x1fffff);
  }
  std::unordered_map<std::int64_t, std::vector<glm::vec3>> cells_;
};

// Distance from p to the triangle (a, b, c) (closest point by Voronoi regions, Ericson 5.1.5).
float triangle_distance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(ap);
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return glm::length(bp);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(p - (a + d1 / (d1 - d3) * ab));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return glm::length(cp);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(p - (a + d2 / (d2 - d6) * ac));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return glm::length(p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)));
  const float denominator = 1.0f / (va + vb + vc);
  return glm::length(p - (a + ab * (vb * denominator) + ac * (vc * denominator)));
}

}  // namespace

struct FrameTracer::State {
  const SceneSources* sources = nullptr;
  std::unique_ptr<ref::EmbreeScene> geometry;
  std::unique_ptr<ref::PathTracer> tracer;
  scene::CameraState camera;
  VertexGrid character_vertices;
  bool character_senders = true;
  bool unshadowed_senders = false;
};

FrameTracer::FrameTracer(std::unique_ptr<State> state) : state_(std::move(state)) {}
FrameTracer::~FrameTracer() = default;
int FrameTracer::width() const { return state_->sources->scene.output.width; }
int FrameTracer::height() const { return state_->sources->scene.output.height; }
bool FrameTracer::character_senders() const { return state_->character_senders; }
bool FrameTracer::unshadowed_senders() const { return state_->unshadowed_senders; }

void FrameTracer::region_masks(FrameReference& reference) const {
  const int w = width(), h = height();
  ref::ReceiverMask none = ref::mask_where(w, h, [](int, int) { return false; });
  reference.ground = reference.contact = reference.other = reference.near_wall = reference.open_floor = none;
  std::vector<std::array<glm::vec3, 3>> walls;  // the static meshes' world triangles
  for (const world::StaticModel& model : state_->sources->world->static_models())
    for (const anim::PosedPrimitive& primitive : model.primitives)
      for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3)
        walls.push_back({primitive.positions[primitive.indices[t]], primitive.positions[primitive.indices[t + 1]],
                         primitive.positions[primitive.indices[t + 2]]});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const scene::Ray ray = scene::ray_through_pixel(state_->camera, w, h, float(x) + 0.5f, float(y) + 0.5f);
      const std::optional<ref::SurfaceHit> hit = state_->geometry->intersect(ray.origin, ray.direction);
      if (!hit || hit->character) continue;
      const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
      if (std::abs(hit->position.y) > 1e-3f || hit->geometric_normal.y < 0.99f) {
        reference.other.receiver[i] = 1;
        continue;
      }
      reference.ground.receiver[i] = 1;
      if (state_->character_vertices.near(hit->position, kContactRadiusM)) reference.contact.receiver[i] = 1;
      if (walls.empty()) continue;
      float nearest = INFINITY;
      for (const auto& t : walls) nearest = std::min(nearest, triangle_distance(hit->position, t[0], t[1], t[2]));
      if (nearest < kNearWallM) reference.near_wall.receiver[i] = 1;
      if (nearest > kOpenFloorM) reference.open_floor.receiver[i] = 1;
    }
}

Result<SceneSources> load_scene_sources(const ChartScene& chart, const ReferenceOptions& options) {
  SceneSources sources;
  sources.scene = chart.scene;
  auto world = world::World::load(sources.scene, {.assets_dir = options.assets_dir, .load_rigs = false});
  if (!world) return world.error();
  sources.world = std::move(*world);
  sources.geometry = ref::make_scene_geometry(*sources.world);
  auto lighting = ref::EnvironmentLight::from_scene(sources.scene, options.lighting, options.reference_order);
  if (!lighting) return lighting.error();
  sources.lighting = std::make_unique<ref::EnvironmentLight>(std::move(*lighting));
  auto background = ref::EnvironmentLight::from_scene(sources.scene, ref::LightingKind::full, options.reference_order);
  if (!background) return background.error();
  sources.background = std::make_unique<ref::EnvironmentLight>(std::move(*background));
  return sources;
}

Result<std::unique_ptr<FrameTracer>> FrameTracer::create(const SceneSources& sources, int frame, bool character_senders,
                                                          bool unshadowed_senders) {
  auto state = std::make_unique<State>();
  state->sources = &sources;
  state->character_senders = character_senders;
  state->unshadowed_senders = unshadowed_senders && character_senders;  // black senders: no difference
  const double time_s = scene::frame_time_s(sources.scene.output, frame);
  world::WorldState world_state;
  if (Status evaluated = sources.world->evaluate(time_s, std::nullopt, world_state); !evaluated) return evaluated.error();
  auto meshes = ref::world_meshes(*sources.world, world_state, sources.geometry);
  if (!meshes) return meshes.error();
  for (const ref::TriangleMesh& mesh : *meshes)
    if (mesh.character)
      for (const glm::vec3& p : mesh.positions) state->character_vertices.add(p);
  auto geometry = ref::EmbreeScene::build(std::move(*meshes));
  if (!geometry) return geometry.error();
  state->geometry = std::make_unique<ref::EmbreeScene>(std::move(*geometry));
  ref::PathTracerSettings settings;
  settings.transport = ref::LightTransport::one_bounce;
  settings.character_senders = character_senders;
  settings.unshadowed_character_senders = state->unshadowed_senders;
  state->tracer = std::make_unique<ref::PathTracer>(*state->geometry, *sources.lighting, *sources.background, settings);
  state->camera = world_state.camera;
  return std::unique_ptr<FrameTracer>(new FrameTracer(std::move(state)));
}

Result<ref::SampleSums> FrameTracer::trace(int spp, std::uint32_t seed, std::uint32_t first_sample,
                                           ref::RenderStats* stats, bool progress, ref::Sampler sampler) const {
  ref::RenderJob job;
  job.sampler = sampler;
  job.width = width();
  job.height = height();
  job.spp = spp;
  job.seed = seed;
  job.first_sample = first_sample;
  ref::ProgressCallback report;
  if (progress)
    report = [](const ref::RenderProgress& p) {
      std::fprintf(stderr, "\r  reference %5.1f%%  %.0f s elapsed, ETA %.0f s   ", 100.0 * p.tiles_done / std::max(p.tiles_total, 1),
                   p.elapsed_s, p.eta_s);
      std::fflush(stderr);
    };
  auto sums = ref::render_samples(*state_->tracer, state_->camera, job, stats, report);
  if (progress) std::fprintf(stderr, "\n");
  return sums;
}

ref::PixelFeatures FrameTracer::features() const {
  return ref::render_features(*state_->geometry, state_->camera, width(), height());
}

namespace {

std::filesystem::path reference_file(const ChartScene& chart, int frame, const ReferenceOptions& options,
                                     const FrameTracer& tracer) {
  // A stream, not operator+ chains: GCC 12 warns falsely (-Wrestrict) on those at -O3.
  std::ostringstream name;
  name << "frame" << frame << '-';
  if (!tracer.character_senders()) name << "nosend-";
  if (tracer.unshadowed_senders()) name << "unshadowed-";
  if (options.lighting == ref::LightingKind::sh)
    name << "sh-n" << options.reference_order;
  else
    name << "full";
  name << '-' << chart.scene.output.width << 'x' << chart.scene.output.height << ".exr";
  return options.cache_dir / chart.name / name.str();
}

}  // namespace

Result<FrameReference> load_or_render_reference(const ChartScene& chart, int frame, const FrameTracer& tracer,
                                                const ReferenceOptions& options) {
  const ref::ReferencePaths paths = ref::reference_paths(reference_file(chart, frame, options, tracer));
  ref::ReferenceRecord record;
  record.scene = chart.name;
  record.frame = frame;
  record.time_s = scene::frame_time_s(chart.scene.output, frame);
  record.width = tracer.width();
  record.height = tracer.height();
  record.transport = !tracer.character_senders()  ? "one-bounce-no-character-senders"
                     : tracer.unshadowed_senders() ? "one-bounce-unshadowed-character-senders"
                                                   : "one-bounce";
  record.lighting = options.lighting == ref::LightingKind::sh ? "sh" : "full";
  record.sh_order = options.reference_order;
  record.seed = kReferenceSeed;

  std::optional<ref::SampleSums> sums;
  std::error_code error;
  if (std::filesystem::exists(paths.record, error)) {
    auto old = ref::read_record(paths.record);
    if (old && ref::record_mismatch(*old, record).empty()) {
      auto previous = ref::read_previous_sums(paths, *old);
      if (previous) {
        sums = std::move(*previous);
        record.samples = old->samples;
        record.seconds = old->seconds;
        record.rays = old->rays;
      }
    }
  }
  const int missing = options.reference_spp - int(record.samples);
  if (missing > 0) {
    std::fprintf(stderr, "bench chart: reference%s %s frame %d, %d spp at %dx%d\n",
                 !tracer.character_senders() ? " without character senders"
                 : tracer.unshadowed_senders() ? " with unshadowed character senders" : "", chart.name.c_str(), frame, missing,
                 record.width, record.height);
    ref::RenderStats stats;
    auto traced = tracer.trace(missing, kReferenceSeed, record.samples, &stats, options.progress);
    if (!traced) return traced.error();
    if (sums) {
      if (Status merged = sums->merge(*traced); !merged) return merged.error();
    } else {
      sums = std::move(*traced);
    }
    record.samples = sums->samples;
    record.seconds += stats.seconds;
    record.rays += stats.rays;
  }
  FrameReference reference;
  const ref::ReferenceImages images = ref::to_images(*sums);
  reference.features = tracer.features();
  if (missing > 0) {
    std::filesystem::create_directories(paths.radiance.parent_path(), error);
    if (error) return make_error(paths.radiance.parent_path().string() + ": cannot create: " + error.message());
    if (Status written = ref::write_reference(paths, images, reference.features, record, nullptr); !written)
      return written.error();
  }
  reference.radiance = images.radiance;
  reference.indirect = images.indirect;
  reference.receivers = ref::mask_from_image(reference.features.mask);
  reference.character = ref::mask_from_image(reference.features.character);
  tracer.region_masks(reference);
  reference.samples = record.samples;
  reference.trace_seconds = record.seconds;
  return reference;
}

Status attach_chart_regions(FrameReference& reference, const SceneSources& sources, const ReferenceOptions& options) {
  auto lighting = reference_lighting_sh(sources.scene, options.lighting, options.reference_order);
  if (!lighting) return lighting.error();
  // Center rays that hit something but neither the ground nor other geometry hit a character.
  const ref::ReceiverMask character_hits = mask_and_not(mask_and_not(reference.receivers, reference.ground), reference.other);
  ReferenceRegionInputs inputs;
  inputs.features = &reference.features;
  inputs.radiance = &reference.radiance;
  inputs.indirect = &reference.indirect;
  inputs.receivers = &reference.receivers;
  inputs.character = &reference.character;
  inputs.character_hits = &character_hits;
  inputs.contact = &reference.contact;
  inputs.near_wall = &reference.near_wall;
  inputs.open_floor = &reference.open_floor;
  reference.regions = std::make_shared<const ChartRegions>(make_chart_regions(inputs, *lighting));
  return {};
}

Result<ImageScores> score_image(const image::ImageF& test, const FrameReference& reference) {
  ImageScores scores;
  if (reference.regions) {
    auto regions = score_regions(test, reference.radiance, *reference.regions);
    if (!regions) return regions.error();
    scores.regions = *regions;
  }
  auto relative = ref::relative_mse(test, reference.radiance, &reference.receivers);
  if (!relative) return relative.error();
  scores.relative_mse = relative->mean;
  auto rmse = ref::rmse(test, reference.radiance, &reference.receivers);
  if (!rmse) return rmse.error();
  scores.rmse = rmse->mean;
  auto ssim = ref::ssim(test, reference.radiance, &reference.receivers);
  if (!ssim) return ssim.error();
  scores.ssim = ssim->mean;
  auto flip = ref::flip_hdr(test, reference.radiance, &reference.receivers);
  if (!flip) return flip.error();
  scores.flip = flip->flip.mean;
  if (reference.character.count() > 0) {
    auto character = ref::relative_mse(test, reference.radiance, &reference.character);
    if (!character) return character.error();
    scores.character_relative_mse = character->mean;
    const double reference_luminance = ref::mean_luminance(reference.radiance, &reference.character);
    if (reference_luminance > 0.0)
      scores.character_luminance_ratio = ref::mean_luminance(test, &reference.character) / reference_luminance;
  }
  return scores;
}

void add_scores(ChartRow& row, const ImageScores& scores, double weight) {
  row.relative_mse += weight * scores.relative_mse;
  row.rmse += weight * scores.rmse;
  row.ssim += weight * scores.ssim;
  row.flip += weight * scores.flip;
  row.character_relative_mse += weight * scores.character_relative_mse;
  row.character_luminance_ratio += weight * scores.character_luminance_ratio;
  row.regions.add(scores.regions, weight);
}

Result<std::vector<PathTracingScore>> score_path_tracing(const FrameTracer& tracer, const FrameReference& reference,
                                                         const std::vector<int>& sample_counts,
                                                         const ReferenceOptions& options) {
  std::vector<PathTracingScore> scores;
  for (int spp : sample_counts) {
    ref::RenderStats stats;
    auto sums = tracer.trace(spp, kTestSeed, 0, &stats, false);
    if (!sums) return sums.error();
    const ref::ReferenceImages images = ref::to_images(*sums);
    PathTracingScore plain;
    plain.samples = spp;
    plain.milliseconds = stats.seconds * 1e3;
    auto plain_scores = score_image(images.radiance, reference);
    if (!plain_scores) return plain_scores.error();
    plain.scores = *plain_scores;
    scores.push_back(plain);

    const auto start = std::chrono::steady_clock::now();
    const ref::PixelFeatures features = tracer.features();
    ref::GuidedFilterSettings filter;
    filter.radius = options.guided_radius;
    filter.depth_scale = options.guided_depth_scale;
    auto filtered = ref::guided_filter_reference(images, features, filter);
    if (!filtered) return filtered.error();
    PathTracingScore guided;
    guided.samples = spp;
    guided.guided = true;
    guided.milliseconds =
        plain.milliseconds + std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    auto guided_scores = score_image(*filtered, reference);
    if (!guided_scores) return guided_scores.error();
    guided.scores = *guided_scores;
    scores.push_back(guided);
  }
  return scores;
}

}  // namespace proxygi::study
