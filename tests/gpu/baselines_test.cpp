// The prior-work baselines on the GPU (settings::ShadingMethod vertex and ambient_occlusion) against
// their CPU twins (src/render/baselines.h, shading.h) at sample receivers, relative error ≤ 1e-3;
// AO against the closed form of one sphere and never brighter than unshadowed; the vertex method
// converging to the image-space method as the ground grid gets denser.
#include <algorithm>
#include <cmath>
#include <map>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/baselines.h"
#include "render/ground_grid.h"

namespace proxygi::gpu {
namespace {

using BaselineTest = testing::GpuTest;
constexpr float kPi = 3.14159265358979f;

// The fixture scene (white sky, camera looking down at the origin) drawn from `ground`.
testing::RenderedFrame render_frame(Context& context, settings::ShadingMethod method, std::uint32_t size, std::uint32_t scale,
                                    const render::GroundGrid& ground, const std::vector<render::Sphere>& spheres,
                                    int order = 4) {
  FrameConfig config;
  config.render.method = method;
  config.width = config.height = size;
  config.render.receiver_scale = scale;
  return testing::render_fixture_frame(context, config, testing::constant_sky_sh(order, 1.0), order, ground, spheres);
}

render::GroundGrid grid(float half_fine, float per_metre) {
  return render::make_ground_grid(20.0f, glm::vec2(-half_fine), glm::vec2(half_fine), per_metre);
}

float relative_error(const glm::vec3& gpu, const glm::vec3& cpu) {
  return glm::length(gpu - cpu) / std::max(glm::length(cpu), 1e-3f);
}

const std::vector<render::Sphere> kTwoSpheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}},
                                                 {{0.7f, 0.3f, 0.4f}, 0.3f, {0.1f, 0.2f, 0.9f}}};

TEST(GroundGrid, CoversTheSquareWithBlockOrderedVertices) {
  const auto ground = render::make_ground_grid(20.0f, {-2.0f, -1.0f}, {2.0f, 1.0f}, 4.0f);
  EXPECT_EQ(ground.lines_x, 17 + 2);  // 16 cells over 4 m, plus both edges
  EXPECT_EQ(ground.lines_z, 9 + 2);
  ASSERT_EQ(ground.positions.size(), std::size_t(ground.lines_x * ground.lines_z));
  float area = 0.0f;
  for (std::size_t t = 0; t < ground.indices.size(); t += 3) {
    const glm::vec3 a = ground.positions[ground.indices[t]], b = ground.positions[ground.indices[t + 1]],
                    c = ground.positions[ground.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(n.y, 0.0f) << "triangle " << t / 3 << " is not counter-clockwise seen from +Y";
    area += 0.5f * n.y;
  }
  EXPECT_NEAR(area, 400.0f, 1e-2f);
  // Each group of 64 receivers is one 8×8 block of grid lines: the second group is columns
  // 8..15 (x = −0.25 .. 1.5 m) of rows 0..7, so tiled culling bounds a compact patch.
  glm::vec2 low(1e9f), high(-1e9f);
  for (std::size_t i = 64; i < 128; ++i) {
    low = glm::min(low, glm::vec2(ground.positions[i].x, ground.positions[i].z));
    high = glm::max(high, glm::vec2(ground.positions[i].x, ground.positions[i].z));
  }
  EXPECT_NEAR(low.x, -0.25f, 1e-5f);
  EXPECT_NEAR(high.x, 1.5f, 1e-5f);
}

TEST_F(BaselineTest, AmbientOcclusionMatchesCpuTwinAndNeverBrightens) {
  const auto ground = grid(2.0f, 1.0f);
  auto rendered = render_frame(context(), settings::ShadingMethod::ambient_occlusion, 64, 2, ground, kTwoSpheres);
  auto unshadowed = render_frame(context(), settings::ShadingMethod::ambient_occlusion, 64, 2, ground, {});
  ASSERT_TRUE(rendered.frame && unshadowed.frame);
  auto positions = rendered.frame->read_receiver_positions();
  auto normals = rendered.frame->read_receiver_normals();
  auto direct = rendered.frame->read_direct();
  auto indirect = rendered.frame->read_indirect();
  auto hdr = rendered.frame->read_hdr();
  auto hdr_unshadowed = unshadowed.frame->read_hdr();
  ASSERT_TRUE(positions.ok() && normals.ok() && direct.ok() && indirect.ok() && hdr.ok() && hdr_unshadowed.ok());
  int checked = 0, occluded = 0;
  for (int y = 0; y < positions->height; ++y)
    for (int x = 0; x < positions->width; ++x) {
      const glm::vec4 p = positions->at(x, y);
      if (p.w <= 0.0f) continue;
      const glm::vec3 n = glm::vec3(normals->at(x, y));
      const auto cpu = render::ambient_occlusion(rendered.tables, glm::vec3(p), n, kTwoSpheres);
      const glm::vec3 gpu = glm::vec3(direct->at(x, y));
      EXPECT_LE(relative_error(gpu, cpu.irradiance), 1e-3f) << "AO irradiance at " << x << "," << y;
      EXPECT_NEAR(direct->at(x, y).w, cpu.unoccluded, 1e-3f * cpu.unoccluded) << "A at " << x << "," << y;
      EXPECT_EQ(glm::vec3(indirect->at(x, y)), glm::vec3(0.0f)) << "AO has no bounce light";
      const glm::vec3 open = render::unshadowed_irradiance(rendered.tables, glm::vec3(p), n);
      for (int c = 0; c < 3; ++c) EXPECT_LE(gpu[c], open[c] * (1.0f + 1e-5f)) << "brighter than unshadowed";
      ++checked;
      if (cpu.unoccluded < 0.98f) ++occluded;
    }
  EXPECT_GE(checked, 500);
  EXPECT_GE(occluded, 50) << "the receivers must include occluded ones";
  // Display pixels: the same G-buffer and upsampling weights average smaller values.
  int darker = 0;
  for (std::size_t i = 0; i < hdr->pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(hdr->pixels[i][c], hdr_unshadowed->pixels[i][c] * (1.0f + 1e-5f)) << "pixel " << i;
      if (hdr->pixels[i][c] < 0.98f * hdr_unshadowed->pixels[i][c]) ++darker;
    }
  EXPECT_GE(darker, 100);
}

TEST_F(BaselineTest, AmbientOcclusionOfOneSphereIsTheClosedForm) {
  // Under a white sky (E(N) = π) one sphere above the receiver's horizon removes exactly
  // π s² cos β: AO is exact for a single blocker (SHEXP at order 4 is not: frame_test).
  const render::Sphere sphere{{0.0f, 1.2f, 0.0f}, 0.4f, {0.5f, 0.5f, 0.5f}};
  auto rendered = render_frame(context(), settings::ShadingMethod::ambient_occlusion, 64, 1, grid(2.0f, 1.0f), {sphere});
  ASSERT_TRUE(rendered.frame);
  auto positions = rendered.frame->read_receiver_positions();
  auto direct = rendered.frame->read_direct();
  ASSERT_TRUE(positions.ok() && direct.ok());
  const float fade_end = 1.0f / 15.0f + 4.0f / 255.0f;  // beyond the influence fade of the 256-row table
  int checked = 0;
  for (int y = 0; y < positions->height; y += 2)
    for (int x = 0; x < positions->width; x += 2) {
      const glm::vec4 p = positions->at(x, y);
      if (p.w <= 0.0f) continue;
      const glm::vec3 to_center = sphere.center - glm::vec3(p);
      const float sine = sphere.radius / glm::length(to_center);
      const float cos_beta = to_center.y / glm::length(to_center);
      if (cos_beta <= sine || sine <= fade_end) continue;
      const float lost = kPi * sine * sine * cos_beta;
      EXPECT_NEAR(direct->at(x, y).r, kPi - lost, 1e-3f * lost + 1e-5f * kPi) << x << "," << y << " s=" << sine;
      ++checked;
    }
  EXPECT_GE(checked, 50);
}

// Per-vertex values of the ground grid's vertices (receiver i = vertex i of the one draw).
TEST_F(BaselineTest, VertexReceiversShadingAndInterpolationMatchCpuTwins) {
  const auto ground = grid(2.0f, 6.0f);
  auto rendered = render_frame(context(), settings::ShadingMethod::vertex, 64, 4, ground, kTwoSpheres);
  ASSERT_TRUE(rendered.frame);
  const SoftGiFrame& frame = *rendered.frame;
  EXPECT_EQ(frame.config().receiver_width() * frame.config().receiver_height(),
            round_up_to_receiver_group(std::uint32_t(ground.positions.size())));
  auto positions = frame.read_receiver_positions();
  auto normals = frame.read_receiver_normals();
  auto log_occlusion = frame.read_log_occlusion();
  auto direct = frame.read_direct();
  auto indirect = frame.read_indirect();
  auto shaded = frame.read_shaded();
  auto gbuffer = frame.read_gbuffer_positions();
  auto albedo = frame.read_gbuffer_albedo();
  auto irradiance = frame.read_irradiance();
  auto hdr = frame.read_hdr();
  ASSERT_TRUE(positions.ok() && normals.ok() && log_occlusion.ok() && direct.ok() && indirect.ok() && shaded.ok() &&
              gbuffer.ok() && albedo.ok() && irradiance.ok() && hdr.ok());

  // Receivers: vertex i exactly, then empty padding.
  for (std::size_t i = 0; i < positions->pixels.size(); ++i) {
    if (i >= ground.positions.size()) {
      EXPECT_EQ(positions->pixels[i].w, 0.0f) << "padding receiver " << i;
      continue;
    }
    const auto expected = render::vertex_receiver(ground.positions[i], ground.normals[i]);
    EXPECT_EQ(positions->pixels[i], expected.position_depth) << "receiver " << i;
    EXPECT_EQ(normals->pixels[i], expected.normal) << "receiver " << i;
  }
  // Shading per vertex: the image-space twins at the vertex.
  int shadowed = 0, lit_by_bounce = 0;
  const std::size_t count = std::size_t(rendered.tables.settings.sh_order * rendered.tables.settings.sh_order);
  for (std::size_t i = 0; i < ground.positions.size(); i += 7) {
    const glm::vec3 p = ground.positions[i], n = ground.normals[i];
    const auto cpu_log = render::accumulate_log_occlusion(rendered.tables, p, n, kTwoSpheres);
    float difference = 0.0f, norm = 0.0f;
    for (std::size_t c = 0; c < count; ++c) {
      const float gpu = (*log_occlusion)[i * count + c];
      difference += (gpu - cpu_log[c]) * (gpu - cpu_log[c]);
      norm += cpu_log[c] * cpu_log[c];
    }
    EXPECT_LE(std::sqrt(difference), 1e-3f * std::sqrt(norm) + 1e-6f) << "log occlusion at vertex " << i;
    const auto cpu_direct = render::exponentiate_and_shade(rendered.tables, cpu_log, 0.25f, p, n);
    EXPECT_LE(relative_error(glm::vec3(direct->pixels[i]), cpu_direct.irradiance), 1e-3f) << "direct at vertex " << i;
    const auto cpu_indirect = render::accumulate_indirect(rendered.tables, p, n, kTwoSpheres, direct->pixels[i].w);
    EXPECT_LE(relative_error(glm::vec3(indirect->pixels[i]), cpu_indirect.irradiance), 1e-3f)
        << "indirect at vertex " << i;
    if (norm > 1e-4f) ++shadowed;
    if (cpu_indirect.irradiance.r > 1e-3f) ++lit_by_bounce;
  }
  EXPECT_GE(shadowed, 20);
  EXPECT_GE(lit_by_bounce, 20);

  // Display pixels: E is the linear interpolation of the vertex values over the pixel's triangle.
  std::map<std::pair<float, float>, std::size_t> vertex_at;
  std::vector<float> xs, zs;
  for (std::size_t i = 0; i < ground.positions.size(); ++i) {
    vertex_at[{ground.positions[i].x, ground.positions[i].z}] = i;
    xs.push_back(ground.positions[i].x);
    zs.push_back(ground.positions[i].z);
  }
  for (auto* lines : {&xs, &zs}) {
    std::sort(lines->begin(), lines->end());
    lines->erase(std::unique(lines->begin(), lines->end()), lines->end());
  }
  int checked = 0;
  for (int y = 0; y < 64; y += 3)
    for (int x = 0; x < 64; x += 3) {
      const glm::vec4 p = gbuffer->at(x, y);
      if (p.w <= 0.0f) continue;
      const std::size_t column = std::size_t(std::upper_bound(xs.begin(), xs.end(), p.x) - xs.begin()) - 1;
      const std::size_t row = std::size_t(std::upper_bound(zs.begin(), zs.end(), p.z) - zs.begin()) - 1;
      if (column + 1 >= xs.size() || row + 1 >= zs.size()) continue;
      auto vertex = [&](std::size_t i, std::size_t j) { return vertex_at.at({xs[i], zs[j]}); };
      const std::size_t corner = vertex(column, row), next_x = vertex(column + 1, row);
      const std::size_t next_z = vertex(column, row + 1), far = vertex(column + 1, row + 1);
      const bool first =
          (p.x - xs[column]) / (xs[column + 1] - xs[column]) + (p.z - zs[row]) / (zs[row + 1] - zs[row]) <= 1.0f;
      const std::size_t a = first ? corner : far, b = next_z, c = next_x;
      const glm::vec3 expected = render::interpolate_triangle(
          glm::vec3(p), ground.positions[a], ground.positions[b], ground.positions[c], glm::vec3(shaded->pixels[a]),
          glm::vec3(shaded->pixels[b]), glm::vec3(shaded->pixels[c]));
      EXPECT_LE(relative_error(glm::vec3(irradiance->at(x, y)), expected), 1e-3f)
          << "interpolated E at " << x << "," << y;
      const glm::vec3 radiance = glm::vec3(albedo->at(x, y)) / kPi * glm::vec3(irradiance->at(x, y));
      EXPECT_LE(relative_error(glm::vec3(hdr->at(x, y)), radiance), 1e-3f) << "composite at " << x << "," << y;
      ++checked;
    }
  EXPECT_GE(checked, 200);
}

// RMS over ground pixels within `half` m of the origin of (E_vertex − E_image) / π, π being the
// unshadowed irradiance under the white sky.
float vertex_against_image(Context& context, const render::GroundGrid& vertex_ground, float half) {
  const auto flat = grid(2.0f, 1.0f);
  auto image = render_frame(context, settings::ShadingMethod::image_space, 96, 1, flat, kTwoSpheres);
  auto vertex = render_frame(context, settings::ShadingMethod::vertex, 96, 1, vertex_ground, kTwoSpheres);
  EXPECT_TRUE(image.frame && vertex.frame);
  if (!image.frame || !vertex.frame) return 1e9f;
  auto gbuffer = image.frame->read_gbuffer_positions();
  auto image_e = image.frame->read_irradiance();
  auto vertex_e = vertex.frame->read_irradiance();
  EXPECT_TRUE(gbuffer.ok() && image_e.ok() && vertex_e.ok());
  double sum = 0.0;
  int pixels = 0;
  for (std::size_t i = 0; i < gbuffer->pixels.size(); ++i) {
    const glm::vec4 p = gbuffer->pixels[i];
    if (p.w <= 0.0f || std::abs(p.x) > half || std::abs(p.z) > half) continue;
    const glm::vec3 difference = glm::vec3(vertex_e->pixels[i] - image_e->pixels[i]) / kPi;
    sum += glm::dot(difference, difference) / 3.0;
    ++pixels;
  }
  EXPECT_GE(pixels, 2000);
  return float(std::sqrt(sum / std::max(pixels, 1)));
}

TEST_F(BaselineTest, VertexMethodApproachesImageSpaceOnADenseGrid) {
  // Image space at k = 1 shades every pixel's own point, so the only difference left is the
  // vertex method's linear interpolation, whose error falls as h² (h: vertex spacing). The
  // tolerance, an RMS of 0.1 % of the unshadowed E, is a quarter of one 8-bit display step
  // (1/255), so a grid that passes is indistinguishable on screen; 32 vertices per metre
  // (h = 3.1 cm, measured 0.026 %) passes with room for driver rounding, and 2 per metre
  // (h = 50 cm, coarser than the 0.3–0.5 m spheres' penumbrae, measured 2.7 %) must fail it.
  const float dense = vertex_against_image(context(), grid(2.0f, 32.0f), 1.8f);
  const float coarse = vertex_against_image(context(), grid(2.0f, 2.0f), 1.8f);
  std::printf("vertex vs image space, RMS of E/pi: %.5f at 32 vertices/m, %.5f at 2 vertices/m\n", dense, coarse);
  EXPECT_LE(dense, 1e-3f);
  EXPECT_GT(coarse, 1e-3f) << "a coarse grid must fail the dense grid's tolerance";
}

TEST_F(BaselineTest, OutputsAreFiniteAndNonNegative) {
  const std::vector<render::Sphere> spheres = {{{0.0f, 0.2f, 0.0f}, 0.5f, {1.0f, 1.0f, 1.0f}},  // straddles the plane
                                               {{0.1f, 0.3f, 0.1f}, 0.4f, {1.0f, 0.0f, 0.0f}},  // heavy overlap
                                               {{-0.5f, 0.05f, 0.3f}, 0.2f, {0.0f, 1.0f, 0.0f}}};
  for (settings::ShadingMethod method : {settings::ShadingMethod::vertex, settings::ShadingMethod::ambient_occlusion}) {
    auto rendered = render_frame(context(), method, 48, 4, grid(2.0f, 8.0f), spheres, 6);
    ASSERT_TRUE(rendered.frame);
    auto hdr = rendered.frame->read_hdr();
    auto direct = rendered.frame->read_direct();
    auto indirect = rendered.frame->read_indirect();
    ASSERT_TRUE(hdr.ok() && direct.ok() && indirect.ok());
    for (const auto* image : {&*hdr, &*direct, &*indirect})
      for (const auto& pixel : image->pixels)
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(pixel[c])) << "method " << int(method);
          ASSERT_GE(pixel[c], 0.0f) << "method " << int(method);
        }
  }
}

}  // namespace
}  // namespace proxygi::gpu
