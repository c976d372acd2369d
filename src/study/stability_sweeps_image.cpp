// S5 silhouettes and thin features, and S7 camera crawl, on the small CPU frame
// (stability_frame.h): a posed "character" of five spheres standing on the ground.
#include <algorithm>
#include <cmath>
#include <string>

#include "study/stability_frame.h"
#include "study/stability_sweep_parts.h"

namespace proxygi::study {

std::vector<render::Sphere> five_sphere_character() {
  const glm::vec3 albedo(0.8f);
  return {{{0.0f, 0.25f, 0.0f}, 0.25f, albedo}, {{0.0f, 0.62f, 0.0f}, 0.15f, albedo}, {{0.0f, 0.85f, 0.0f}, 0.1f, albedo},
          {{0.24f, 0.6f, 0.0f}, 0.06f, albedo}, {{-0.24f, 0.6f, 0.0f}, 0.06f, albedo}};
}

namespace {

constexpr float kEpsilon = 0.01f;  // settings::RenderSettings::bilateral_depth_epsilon's default

const settings::Upsampling kUpsamplers[2] = {settings::Upsampling::bilateral, settings::Upsampling::bilinear};
const char* kUpsamplerNames[2] = {"bilateral", "bilinear"};

// Per-pixel values in units of u (the pixel's own unshadowed shade / 255).
ref::Plane in_u(const SweepImage& image) {
  ref::Plane out = image.shade;
  for (std::size_t i = 0; i < out.values.size(); ++i) {
    const float open = image.pixel_unshadowed.values[i];
    out.values[i] = open > 0.0f ? out.values[i] / (open * float(kDisplayStep)) : 0.0f;
  }
  return out;
}

void count_image(SweepResult& sweep, const SweepImage& image, const SweepGBuffer& g) {
  const ref::ReceiverMask covered = ref::mask_where(g.size, g.size, [&](int x, int y) { return g.label[std::size_t(y * g.size + x)] >= 0; });
  sweep.bounds.merge(count_bounds(image.shade, image.unshadowed, &covered));
}

// S5's scene at one camera: the character, five receiver-only poles 1–16 px wide standing 0.5 m
// behind it (each pole's radius set from this camera's pixel size at its axis), and a wall 2 m
// behind the character facing the camera's side, so the poles stand before a far backdrop.
constexpr int kPoleWidthsPx[5] = {1, 2, 4, 8, 16};

SweepGeometry silhouette_scene(const SweepCamera& camera, int size) {
  SweepGeometry geometry{five_sphere_character(), {}, {}};
  const glm::vec3 toward_camera = glm::normalize(glm::vec3(camera.eye.x, 0.0f, camera.eye.z));
  const glm::vec3 across = glm::cross(kUp, toward_camera);
  const float lateral[5] = {0.36f, 0.5f, -0.42f, 0.72f, -0.7f};  // metres across the view, clear of the character
  for (int i = 0; i < 5; ++i) {
    const glm::vec3 foot = -0.5f * toward_camera + lateral[i] * across;
    const float width = float(kPoleWidthsPx[i]) * pixel_size_at(camera, size, eye_depth(camera, foot + 0.5f * kUp));
    geometry.poles.push_back({glm::vec2(foot.x, foot.z), 0.5f * width, 1.0f});
  }
  geometry.walls.push_back({-2.0f * toward_camera, toward_camera, 1.3f, 0.9f});
  return geometry;
}

SweepResult silhouettes(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S5";
  sweep.title = "silhouettes and thin features: a five-sphere character and poles 1-16 px wide before a far wall, 1/k receivers "
                "against k = 1 (n = 4, sky)";
  sweep.x_label = "receiver scale k";
  sweep.log_x = true;
  sweep.metrics = {{"edge-band error / interior error (interior floored at 0.1u)", "ratio", 2.0},
                   {"edge-band mean error", "u", INFINITY},
                   {"thin features (poles): mean error / interior error (interior floored at 0.1u)", "ratio", 2.0},
                   {"no-match pixels (no tap's eq. 11 factor reaches 1/2)", "%", 0.5}};
  sweep.trace_x_label = "pole width / k (receiver spacing)";
  sweep.trace_log_x = true;
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const int size = options.quick ? 96 : 128;
  double worst_ratio[2] = {-1.0, -1.0};
  for (float distance : {1.0f, 4.0f, 16.0f}) {
    SweepCamera camera;
    camera.eye = glm::vec3(0.0f, 0.5f, 0.0f) + distance * glm::vec3(1.2f, 0.9f, 2.2f);
    camera.target = glm::vec3(0.0f, 0.45f, 0.0f);
    camera.fov_y_degrees = 40.0f / distance;  // the character keeps its size; the ground recedes to the horizon
    const SweepGeometry geometry = silhouette_scene(camera, size);
    const SweepGBuffer g = trace_gbuffer(geometry, camera, size);
    const SweepImage full = render_sweep_frame(tables, geometry.spheres, g, 1, settings::Upsampling::bilinear, kEpsilon);
    count_image(sweep, full, g);
    const ref::Plane reference = in_u(full);
    auto label_at = [&](int x, int y) { return g.label[std::size_t(y * size + x)]; };
    const ref::ReceiverMask covered = ref::mask_where(size, size, [&](int x, int y) { return label_at(x, y) >= 0; });
    const ref::ReceiverMask poles = ref::mask_where(size, size, [&](int x, int y) { return g.is_pole(label_at(x, y)); });
    std::vector<ref::ReceiverMask> each_pole;
    for (int pole = 0; pole < g.poles; ++pole)
      each_pole.push_back(ref::mask_where(size, size, [&](int x, int y) { return label_at(x, y) == g.pole_label(pole); }));
    // Silhouettes by label (sphere, pole, wall, ground or sky): at 16x the character stands only
    // 2.4 % of the eye depth before the ground, below any depth-jump threshold the near ground passes.
    const ref::ReceiverMask edge = mask_and_not(mask_and(label_edge_band_mask(size, size, g.label, 1), covered), poles);
    const ref::ReceiverMask interior = mask_and_not(mask_and_not(covered, edge), poles);
    const std::string at_distance = "distance " + fixed(distance, 0) + "x";
    for (int k : {2, 4, 8})
      for (int u = 0; u < 2; ++u) {
        const SweepImage image = render_sweep_frame(tables, geometry.spheres, g, k, kUpsamplers[u], kEpsilon);
        count_image(sweep, image, g);
        const ref::Plane test = in_u(image);
        const ErrorSummary at_edges = absolute_error(test, reference, &edge);
        const ErrorSummary inside = absolute_error(test, reference, &interior);
        const ErrorSummary on_poles = absolute_error(test, reference, &poles);
        const std::string series = std::string(kUpsamplerNames[u]) + " " + at_distance;
        const double ratio = at_edges.mean / std::max(inside.mean, 0.1);
        add_point(sweep, kUpsamplerNames[u], series, k, 0, ratio);
        add_point(sweep, kUpsamplerNames[u], series, k, 1, at_edges.mean);
        add_point(sweep, kUpsamplerNames[u], series, k, 2, on_poles.mean / std::max(inside.mean, 0.1));
        if (kUpsamplers[u] == settings::Upsampling::bilateral) {
          std::size_t rejected = 0;
          for (std::size_t i = 0; i < image.no_match.size(); ++i) rejected += covered.contains(i) && image.no_match[i];
          add_point(sweep, kUpsamplerNames[u], series, k, 3, 100.0 * double(rejected) / double(std::max<std::size_t>(covered.count(), 1)));
        }
        SweepTrace by_width{"mean error on a pole against k = 1 (u), " + at_distance, std::string(kUpsamplerNames[u]) + " k=" + std::to_string(k), {}, {}};
        for (int pole = 0; pole < g.poles; ++pole) {
          const ref::ReceiverMask& one = each_pole[std::size_t(pole)];
          if (one.count() == 0) continue;
          by_width.x.push_back(double(kPoleWidthsPx[pole]) / k);
          by_width.y.push_back(absolute_error(test, reference, &one).mean);
        }
        sweep.traces.push_back(std::move(by_width));
        if (ratio > worst_ratio[u]) {  // the heat map at this method's worst point
          worst_ratio[u] = ratio;
          SweepHeatMap map{std::string(kUpsamplerNames[u]) + " k=" + std::to_string(k) + ", " + at_distance +
                               ": |x - x(k=1)|, edge/interior " + fixed(ratio, 1),
                           "u", ref::Plane(size, size, NAN)};
          for (std::size_t i = 0; i < map.values.values.size(); ++i)
            if (covered.contains(i)) map.values.values[i] = std::abs(test.values[i] - reference.values[i]);
          if (sweep.heat_maps.size() <= std::size_t(u)) sweep.heat_maps.resize(std::size_t(u) + 1);
          sweep.heat_maps[std::size_t(u)] = std::move(map);
        }
      }
  }
  sweep.notes.push_back("edge band: 1 px around every silhouette (study::label_edge_band_mask), pole pixels left out; thin features: the "
                        "pole pixels (poles 1, 2, 4, 8, 16 px wide, receivers only: they cast no shadow, the character shadows them); "
                        "the camera's field of view narrows with its distance so the character keeps its size on screen");
  return sweep;
}

SweepResult camera_crawl(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S7";
  sweep.title = "camera crawl: static character and ground, the camera orbits 20 deg and dollies in (n = 4, sky)";
  sweep.x_label = "receiver scale k";
  sweep.log_x = true;
  // F as the notes define it (no reference), and F of the error against the frame's own k = 1 image
  // (every pixel shaded exactly by the twin): the first includes the pixel grid sliding over the
  // shading's gradients, which no method avoids; the second is the receivers' crawl alone.
  sweep.metrics = {{"crawl: flicker of the error against k = 1, mean", "u", 0.5}, {"crawl: flicker of the error against k = 1, p99", "u", 2.0},
                   {"flicker F mean (no reference)", "u", 0.5}, {"flicker F p99 (no reference)", "u", 2.0}};
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const std::vector<render::Sphere> spheres = five_sphere_character();
  const int size = options.quick ? 64 : 128;
  const int frames = options.quick ? 8 : 60;
  std::vector<SweepCamera> cameras;
  std::vector<SweepGBuffer> gbuffers;
  for (int t = 0; t < frames; ++t) {
    const float a = glm::radians(20.0f) * float(t) / float(frames - 1);
    const float radius = 2.6f - 0.4f * float(t) / float(frames - 1);
    SweepCamera camera;
    camera.eye = glm::vec3(radius * std::sin(a), 1.3f, radius * std::cos(a));
    camera.target = glm::vec3(0.0f, 0.4f, 0.0f);
    cameras.push_back(camera);
    gbuffers.push_back(trace_gbuffer(spheres, camera, size));
  }
  std::vector<Reprojection> to_frame, to_previous;
  for (int t = 0; t < frames; ++t) to_frame.push_back(reproject(gbuffers.front(), cameras[std::size_t(t)], gbuffers[std::size_t(t)]));
  for (int t = 1; t < frames; ++t)
    to_previous.push_back(reproject(gbuffers[std::size_t(t)], cameras[std::size_t(t - 1)], gbuffers[std::size_t(t - 1)]));
  double worst_crawl[2] = {-1.0, -1.0};
  std::vector<ref::Plane> exact;  // k = 1
  for (int k : {1, 2, 4, 8})
    for (int u = 0; u < (k == 1 ? 1 : 2); ++u) {
      std::vector<ref::Plane> images, errors;
      for (int t = 0; t < frames; ++t) {
        const SweepImage image = render_sweep_frame(tables, spheres, gbuffers[std::size_t(t)], k, kUpsamplers[u], kEpsilon);
        count_image(sweep, image, gbuffers[std::size_t(t)]);
        images.push_back(in_u(image));
        if (k == 1) exact.push_back(images.back());
        errors.push_back(images.back());
        for (std::size_t i = 0; i < errors.back().values.size(); ++i) errors.back().values[i] -= exact[std::size_t(t)].values[i];
      }
      const FlickerSummary crawl = flicker(errors, to_frame);
      const FlickerSummary f = flicker(images, to_frame);
      const std::string method = k == 1 ? "k1" : kUpsamplerNames[u];
      const std::string series = k == 1 ? std::string("every pixel") : method;
      if (k > 1) {
        // Traces: the mean |error| against k = 1 and the temporal-gradient error E_delta against k = 1
        // (exact reprojection into the previous frame), per frame.
        const std::string name = method + " k=" + std::to_string(k);
        SweepTrace level{"mean |x - x(k=1)| over the frame (u)", name, {}, {}};
        SweepTrace gradient{"temporal-gradient error E_delta against k = 1, mean (u)", name, {}, {}};
        for (int t = 0; t < frames; ++t) {
          level.x.push_back(t);
          level.y.push_back(absolute_error(images[std::size_t(t)], exact[std::size_t(t)]).mean);
          if (t == 0) continue;
          gradient.x.push_back(t);
          gradient.y.push_back(temporal_gradient_error(images[std::size_t(t - 1)], images[std::size_t(t)], exact[std::size_t(t - 1)],
                                                       exact[std::size_t(t)], to_previous[std::size_t(t - 1)])
                                   .mean);
        }
        sweep.traces.push_back(std::move(level));
        sweep.traces.push_back(std::move(gradient));
        if (crawl.mean > worst_crawl[u]) {  // heat map: each point's flicker of the error, in frame 0
          worst_crawl[u] = crawl.mean;
          SweepHeatMap map{name + ": flicker of the error against k = 1 (std over frames), mean " + fixed(crawl.mean, 2) + "u", "u",
                           ref::Plane(size, size, NAN)};
          for (std::size_t p = 0; p < map.values.values.size(); ++p) {
            double sum = 0.0, squares = 0.0;
            bool seen = true;
            for (int t = 0; t < frames && seen; ++t) {
              const int q = to_frame[std::size_t(t)].source[p];
              if (q < 0) seen = false;
              else sum += errors[std::size_t(t)].values[std::size_t(q)], squares += double(errors[std::size_t(t)].values[std::size_t(q)]) * errors[std::size_t(t)].values[std::size_t(q)];
            }
            if (seen) map.values.values[p] = float(std::sqrt(std::max(0.0, squares / frames - (sum / frames) * (sum / frames))));
          }
          if (sweep.heat_maps.size() <= std::size_t(u)) sweep.heat_maps.resize(std::size_t(u) + 1);
          sweep.heat_maps[std::size_t(u)] = std::move(map);
        }
      }
      if (k > 1) {
        add_point(sweep, method, series, k, 0, crawl.mean);
        add_point(sweep, method, series, k, 1, crawl.p99);
      }
      add_point(sweep, method, series, k, 2, f.mean);
      add_point(sweep, method, series, k, 3, f.p99);
    }
  sweep.trace_x_label = "frame";
  sweep.notes.push_back("exact reprojection: each world point of frame 0 is projected into every frame and kept where the "
                        "same surface is seen there (study::reproject); F at k = 1 is the floor of the metric itself");
  return sweep;
}

}  // namespace

SweepResult sweep_silhouettes(const StabilityOptions& options) { return timed(silhouettes, options); }
SweepResult sweep_camera_crawl(const StabilityOptions& options) { return timed(camera_crawl, options); }

}  // namespace proxygi::study
