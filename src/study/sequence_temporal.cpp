#include "study/sequence_temporal.h"

#include <algorithm>
#include <cmath>

#include "ref/embree_scene.h"
#include "scene/camera.h"

namespace proxygi::study {
namespace {

constexpr float kDepthTolerance = 0.01f;  // a reprojected point is visible within 1 % of the eye depth

glm::vec3 point_on(const std::vector<ref::TriangleMesh>& meshes, const ref::SurfaceHit& hit) {
  const ref::TriangleMesh& mesh = meshes[hit.mesh];
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(hit.triangle)];
  const float u = hit.barycentric.x, v = hit.barycentric.y;
  return (1.0f - u - v) * mesh.positions[tri[0]] + u * mesh.positions[tri[1]] + v * mesh.positions[tri[2]];
}

float eye_depth(const scene::CameraState& camera, const glm::vec3& point) {
  return glm::dot(point - camera.eye, glm::normalize(camera.target - camera.eye));
}

// Keeps only the pixels of `from` inside `region` (the metrics score pixels with a source).
Reprojection restricted(Reprojection r, const std::vector<std::uint8_t>& region) {
  for (std::size_t i = 0; i < r.source.size(); ++i)
    if (!region[i]) r.source[i] = -1;
  return r;
}

void accumulate(ErrorSummary& total, const ErrorSummary& one, std::size_t& terms) {
  if (one.pixels == 0) return;
  total.mean += one.mean;
  total.max = std::max(total.max, one.max);
  total.pixels += one.pixels;
  ++terms;
}

// E_Δ, pop and the reference's mean over one region (the flicker is scored once, score_sequence).
TemporalScores score_region(std::span<const ref::Plane> test, std::span<const ref::Plane> reference, const TracedSequence& sequence,
                            const std::vector<std::vector<Reprojection>>& to_previous_next,
                            const std::vector<std::vector<std::uint8_t>>& region) {
  TemporalScores scores;
  const std::size_t n = sequence.frames.size();
  std::size_t gradient_terms = 0, pop_terms = 0;
  for (std::size_t t = 1; t < n; ++t) {
    const Reprojection back = restricted(to_previous_next[t][0], region[t]);
    const ErrorSummary g = temporal_gradient_error(test[t - 1], test[t], reference[t - 1], reference[t], back);
    accumulate(scores.gradient, g, gradient_terms);
    scores.reprojected += g.pixels;
    if (t + 1 < n) {
      const Reprojection forward = restricted(to_previous_next[t][1], region[t]);
      accumulate(scores.pop,
                 pop_error(test.subspan(t - 1).first<3>(), reference.subspan(t - 1).first<3>(), back, forward), pop_terms);
    }
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t t = 0; t < n; ++t)
    for (std::size_t i = 0; i < region[t].size(); ++i)
      if (region[t][i]) sum += reference[t].values[i], ++count;
  scores.reference_mean = count > 0 ? sum / double(count) : 0.0;
  if (gradient_terms > 0) scores.gradient.mean /= double(gradient_terms);
  if (pop_terms > 0) scores.pop.mean /= double(pop_terms);
  return scores;
}

}  // namespace

Result<TracedSequence> trace_sequence(const world::World& world, const ref::SceneGeometry& geometry, int first, int last,
                                      int width, int height) {
  if (last < first) return make_error("trace_sequence: frame range " + std::to_string(first) + ":" + std::to_string(last) + " is empty");
  TracedSequence sequence{width, height, {}};
  world::WorldState state;
  for (int frame = first; frame <= last; ++frame) {
    if (Status evaluated = world.evaluate(scene::frame_time_s(world.scene().output, frame), std::nullopt, state); !evaluated)
      return evaluated.error();
    auto meshes = ref::world_meshes(world, state, geometry);
    if (!meshes) return meshes.error();
    SequenceFrame out;
    out.frame = frame;
    out.camera = state.camera;
    out.meshes = *meshes;
    auto embree = ref::EmbreeScene::build(std::move(*meshes));
    if (!embree) return embree.error();
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    out.hits.resize(pixels);
    out.depth.assign(pixels, 0.0f);
    out.character.assign(pixels, 0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const scene::Ray ray = scene::ray_through_pixel(out.camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
        const std::optional<ref::SurfaceHit> hit = embree->intersect(ray.origin, ray.direction);
        if (!hit || hit->mesh == ref::SurfaceHit::kNoTriangle) continue;
        const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
        out.hits[i] = *hit;
        out.depth[i] = eye_depth(out.camera, hit->position);
        out.character[i] = hit->character ? 1 : 0;
      }
    sequence.frames.push_back(std::move(out));
  }
  return sequence;
}

Reprojection reproject_exact(const TracedSequence& sequence, std::size_t from, std::size_t to) {
  const SequenceFrame& a = sequence.frames[from];
  const SequenceFrame& b = sequence.frames[to];
  Reprojection r{sequence.width, sequence.height, std::vector<int>(a.hits.size(), -1)};
  for (std::size_t i = 0; i < a.hits.size(); ++i) {
    if (a.depth[i] <= 0.0f) continue;
    const glm::vec3 moved = point_on(b.meshes, a.hits[i]);  // the same triangle posed at frame `to`
    const float z = eye_depth(b.camera, moved);
    if (z <= 0.0f) continue;
    const glm::vec2 pixel = scene::project_to_pixel(b.camera, sequence.width, sequence.height, moved);
    const int x = int(std::floor(pixel.x)), y = int(std::floor(pixel.y));
    if (x < 0 || y < 0 || x >= sequence.width || y >= sequence.height) continue;
    const std::size_t j = std::size_t(y) * std::size_t(sequence.width) + std::size_t(x);
    if (b.depth[j] <= 0.0f || std::abs(b.depth[j] - z) > kDepthTolerance * z) continue;  // hidden there
    r.source[i] = int(j);
  }
  return r;
}

Result<SequenceScores> score_sequence(std::span<const ref::Plane> test, std::span<const ref::Plane> reference,
                                      const TracedSequence& sequence) {
  const std::size_t n = sequence.frames.size();
  if (test.size() != n || reference.size() != n)
    return make_error("score_sequence: " + std::to_string(test.size()) + " test and " + std::to_string(reference.size()) +
                      " reference frames for a sequence of " + std::to_string(n));
  if (n < 2) return make_error("score_sequence: the temporal metrics need at least 2 frames");
  for (std::size_t t = 0; t < n; ++t)
    if (test[t].width != sequence.width || test[t].height != sequence.height || reference[t].width != sequence.width ||
        reference[t].height != sequence.height)
      return make_error("score_sequence: frame " + std::to_string(sequence.frames[t].frame) + " is not " +
                        std::to_string(sequence.width) + "x" + std::to_string(sequence.height));
  std::vector<std::vector<Reprojection>> to_previous_next(n);
  for (std::size_t t = 0; t < n; ++t) {
    to_previous_next[t].push_back(t > 0 ? reproject_exact(sequence, t, t - 1) : Reprojection{});
    to_previous_next[t].push_back(t + 1 < n ? reproject_exact(sequence, t, t + 1) : Reprojection{});
  }
  auto region = [&](int which) {  // 0 all, 1 character, 2 static world
    std::vector<std::vector<std::uint8_t>> masks;
    for (const SequenceFrame& f : sequence.frames) {
      std::vector<std::uint8_t> m(f.depth.size());
      for (std::size_t i = 0; i < m.size(); ++i)
        m[i] = f.depth[i] > 0.0f && (which == 0 || (which == 1) == (f.character[i] != 0));
      masks.push_back(std::move(m));
    }
    return masks;
  };
  SequenceScores scores;
  const std::vector<std::vector<std::uint8_t>> static_world = region(2);
  scores.all = score_region(test, reference, sequence, to_previous_next, region(0));
  scores.character = score_region(test, reference, sequence, to_previous_next, region(1));
  scores.static_world = score_region(test, reference, sequence, to_previous_next, static_world);
  // Flicker: frame 0's static-world points seen in every frame (a character's shading changes with
  // its pose, so the character region has none and "all" has the static world's).
  std::vector<Reprojection> from_first;
  for (std::size_t t = 0; t < n; ++t) from_first.push_back(restricted(reproject_exact(sequence, 0, t), static_world[0]));
  std::vector<ref::Plane> error;
  for (std::size_t t = 0; t < n; ++t) {
    error.push_back(test[t]);
    for (std::size_t i = 0; i < error.back().values.size(); ++i) error.back().values[i] -= reference[t].values[i];
  }
  scores.static_world.flicker_test = flicker(test, from_first);
  scores.static_world.flicker_reference = flicker(reference, from_first);
  scores.static_world.flicker_error = flicker(error, from_first);
  scores.all.flicker_test = scores.static_world.flicker_test;
  scores.all.flicker_reference = scores.static_world.flicker_reference;
  scores.all.flicker_error = scores.static_world.flicker_error;
  return scores;
}

}  // namespace proxygi::study
