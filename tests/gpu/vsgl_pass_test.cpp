// render.indirect_method vsgl on the GPU (vsgl_lights.comp, indirect.comp:vsgl) against its CPU
// twin (sh/vsgl.h): two sender meshes (the first with per-vertex sender exposures; each K = 1 or 4 lights, by index range or by group: the
// triangles reordered by anim::group_triangles, here with longitude sectors as the vertex groups)
// over a ground plane under a directional sky. The fitted lights match the CPU fit of the same triangles, and the indirect
// irradiance at sample receivers matches sh::vsgl_irradiance at the GPU's receivers (relative
// error ≤ 1e-3, as the other passes' twins). Validation layer on, no message.
#include <cmath>
#include <numbers>

#include "anim/bone_groups.h"
#include "frame_fixture.h"
#include "gpu/transfer.h"
#include "gpu_test_context.h"
#include "sh/basis.h"
#include "sh/environment.h"
#include "sh/vsgl.h"
#include "sh/vsgl_sun.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

using VsglPassTest = testing::GpuTest;

struct Mesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
  glm::vec4 albedo{1.0f};
  std::vector<int> sector;  // per vertex: its longitude φ as a fraction of a turn, times 1000
  std::vector<float> exposure;  // per vertex sender exposure (DrawItem::vsgl_exposure); empty: none
};

Mesh uv_sphere(const glm::vec3& center, float radius, int rings, int segments, const glm::vec4& albedo) {
  Mesh mesh;
  mesh.albedo = albedo;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      const float theta = std::numbers::pi_v<float> * float(r) / float(rings);
      const float phi = 2.0f * std::numbers::pi_v<float> * float(s) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(center + radius * n);
      mesh.normals.push_back(n);
      mesh.sector.push_back(std::min(999, 1000 * s / segments));
    }
  const std::uint32_t row = std::uint32_t(segments + 1);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t i = std::uint32_t(r) * row + std::uint32_t(s);
      mesh.indices.insert(mesh.indices.end(), {i, i + 1, i + row, i + 1, i + row + 1, i + row});
    }
  return mesh;
}

sh::RgbSh sky() {
  sh::RgbSh lighting = testing::constant_sky_sh(4, 1.0);
  const double band1[3][3] = {{0.9, 0.4, 0.3}, {0.8, 0.2, -0.1}, {1.1, 0.1, -0.4}};
  for (int c = 0; c < 3; ++c)
    for (int m = 0; m < 3; ++m) lighting.channels[std::size_t(c)][std::size_t(1 + m)] = band1[c][m];
  return lighting;
}

using Order3 = std::array<std::array<float, 9>, 3>;

// The CPU twin of vsgl_lights.comp's sums: the same VPLs from the same triangles (triangles
// [first, last) of `indices`, sh::triangle_light, each scaled by its vertices' mean exposure when
// the mesh has exposures) lit by `irradiance` (L̃), added to `sums` relative to `origin`.
void add_cpu_sums(sh::VsglSums& sums, const glm::dvec3& origin, const Mesh& mesh, std::span<const std::uint32_t> indices,
                  const Order3& irradiance_order3, std::size_t first, std::size_t last) {
  for (std::size_t t = 3 * first; t < 3 * last; t += 3) {
    glm::dvec3 x[3], n[3], e(1.0);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = indices[t + std::size_t(k)];
      x[k] = glm::dvec3(mesh.positions[v]), n[k] = glm::dvec3(mesh.normals[v]);
      if (!mesh.exposure.empty()) e[k] = mesh.exposure[v];
    }
    sh::add_light(sums, sh::triangle_light(x, n, glm::dvec3(glm::vec3(mesh.albedo)), irradiance_order3, e), origin);
  }
}

// vsgl_lights.comp's light of those triangles, lit by the whole L̃.
std::optional<sh::Vsgl> cpu_light(const Mesh& mesh, std::span<const std::uint32_t> indices,
                                  const render::FrameTables& tables, std::size_t first, std::size_t last) {
  sh::VsglSums sums;
  const glm::dvec3 origin(mesh.positions[indices[3 * first]]);
  add_cpu_sums(sums, origin, mesh, indices, tables.irradiance_order3, first, last);
  return sh::fit_vsgl(sums, origin);
}

// K = render.vsgl_lights lights per sender: 1 (the default) and 4, by index ranges or by groups.
class VsglPassLights : public VsglPassTest,
                       public ::testing::WithParamInterface<std::tuple<int, settings::VsglGrouping>> {};

TEST_P(VsglPassLights, LightsAndIrradianceMatchTheCpuTwin) {
  const auto [per_sender, grouping] = GetParam();
  const bool by_group = grouping == settings::VsglGrouping::bone_groups;
  FrameConfig config;
  config.width = config.height = 64;
  config.frames_in_flight = 1;
  config.render.receiver_scale = 2;
  config.render.indirect_method = settings::IndirectMethod::vsgl;
  config.render.vsgl_lights = per_sender;
  config.render.vsgl_grouping = grouping;
  const render::FrameTables tables = render::make_frame_tables(sky(), config.render);
  const testing::GroundMesh ground = testing::ground_plane(20.0f, 4);
  // 40 × 40 × 2 triangles: more than one workgroup of partials per light.
  Mesh senders[] = {uv_sphere({0.0f, 0.6f, 0.0f}, 0.5f, 40, 40, {0.9f, 0.2f, 0.1f, 1.0f}),
                    uv_sphere({1.3f, 0.35f, 0.6f}, 0.3f, 12, 16, {0.1f, 0.3f, 0.9f, 1.0f})};
  // The first sender has sender exposures (ref/sender_exposure.h): 0 below (buried), rising with
  // the longitude elsewhere; the second has none (exposure 1).
  for (std::size_t v = 0; v < senders[0].positions.size(); ++v)
    senders[0].exposure.push_back(senders[0].normals[v].y < -0.3f ? 0.0f : 0.3f + 0.7f * float(senders[0].sector[v]) / 1000.0f);
  auto exposure = create_buffer_with_data(context(), as_bytes(std::span<const float>(senders[0].exposure)),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ASSERT_TRUE(exposure.ok());
  std::vector<StaticMesh> meshes;
  auto ground_mesh = upload_static_mesh(context(), ground.positions, ground.normals, ground.indices, glm::vec4(0.8f));
  ASSERT_TRUE(ground_mesh.ok());
  meshes.push_back(std::move(*ground_mesh));
  for (const Mesh& sender : senders) {
    auto uploaded = upload_static_mesh(context(), sender.positions, sender.normals, sender.indices, sender.albedo);
    ASSERT_TRUE(uploaded.ok());
    meshes.push_back(std::move(*uploaded));
  }
  // Groups: K longitude sectors of each sender, its triangles reordered by sector.
  std::vector<anim::GroupedTriangles> grouped;
  std::vector<Buffer> grouped_buffers;
  for (const Mesh& sender : senders) {
    std::vector<int> vertex_group;
    for (int sector : sender.sector) vertex_group.push_back(sector * per_sender / 1000);
    grouped.push_back(anim::group_triangles(sender.indices, vertex_group, per_sender));
    auto buffer = create_buffer_with_data(context(), as_bytes(std::span<const std::uint32_t>(grouped.back().indices)),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    ASSERT_TRUE(buffer.ok());
    grouped_buffers.push_back(std::move(*buffer));
  }
  std::vector<DrawItem> draws;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    draws.push_back(meshes[i].draw());
    draws.back().vsgl_light = int(i) - 1;  // the ground sends nothing
    if (i == 1) draws.back().vsgl_exposure = &*exposure;
    if (by_group && i > 0) {
      draws.back().vsgl_indices = &grouped_buffers[i - 1];
      draws.back().vsgl_group_first = grouped[i - 1].first;
    }
  }
  auto frame = SoftGiFrame::create(context(), config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  ASSERT_TRUE(frame.ok()) << frame.message();
  ASSERT_TRUE((*frame)->write_slot(0, testing::look_at({0.5f, 3.0f, 4.0f}, {0.3f, 0.3f, 0.0f}, 60.0f, 1.0f), {}).ok());
  ASSERT_TRUE(context()
                  .submit_and_wait([&](VkCommandBuffer commands) {
                    (*frame)->record(commands, 0, draws, FrameOutput::readback());
                  })
                  .ok());

  auto lights = (*frame)->read_vsgl_lights();
  ASSERT_TRUE(lights.ok());
  ASSERT_EQ(lights->size(), 2u * std::size_t(per_sender));
  std::vector<sh::Vsgl> cpu;
  int unexposed_lights = 0;
  for (std::size_t k = 0; k < lights->size(); ++k) {
    const std::size_t sender = k / std::size_t(per_sender), range = k % std::size_t(per_sender);
    const Mesh& mesh = senders[sender];
    const std::size_t triangles = mesh.indices.size() / 3;
    auto expected = by_group ? cpu_light(mesh, grouped[sender].indices, tables, grouped[sender].first[range],
                                         grouped[sender].first[range + 1])
                             : cpu_light(mesh, mesh.indices, tables, range * triangles / std::size_t(per_sender),
                                         (range + 1) * triangles / std::size_t(per_sender));
    const gpu_layout::VsglLight& gpu = (*lights)[k];
    SCOPED_TRACE("light " + std::to_string(k));
    if (!expected) {  // every triangle of the light has exposure 0 (sender 0's lowest rows): no light
      ++unexposed_lights;
      EXPECT_EQ(glm::vec3(gpu.amplitude), glm::vec3(0.0f));
      continue;
    }
    cpu.push_back(*expected);
    EXPECT_LE(glm::length(glm::dvec3(gpu.axis_sharpness) - expected->axis), 1e-3);
    EXPECT_NEAR(gpu.axis_sharpness.w, expected->sharpness, 1e-3 * expected->sharpness + 1e-6);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu.amplitude[c], expected->amplitude[c], 1e-3 * expected->amplitude[c]);
    EXPECT_LE(glm::length(glm::dvec3(gpu.mean_variance) - expected->mean), 1e-4);
    EXPECT_NEAR(gpu.mean_variance.w, expected->variance, 1e-3 * expected->variance);
  }

  auto positions = (*frame)->read_receiver_positions();
  auto normals = (*frame)->read_receiver_normals();
  auto indirect = (*frame)->read_indirect();
  auto direct = (*frame)->read_direct();
  auto shaded = (*frame)->read_shaded();
  ASSERT_TRUE(positions.ok() && normals.ok() && indirect.ok() && direct.ok() && shaded.ok());
  int checked = 0, lit = 0;
  for (int y = 0; y < positions->height; y += 2)
    for (int x = 0; x < positions->width; x += 2) {
      const glm::vec4 p = positions->at(x, y);
      if (p.w <= 0.0f) continue;
      const glm::dvec3 n(glm::vec3(normals->at(x, y)));
      glm::dvec3 expected(0.0);
      for (const sh::Vsgl& light : cpu) expected += sh::vsgl_irradiance(light, glm::dvec3(glm::vec3(p)), n);
      const glm::vec3 gpu(indirect->at(x, y));
      const float error = glm::length(gpu - glm::vec3(expected)) / std::max(float(glm::length(expected)), 1e-3f);
      EXPECT_LE(error, 1e-3f) << "at " << x << "," << y;
      EXPECT_TRUE(std::isfinite(gpu.r + gpu.g + gpu.b) && gpu.r >= 0.0f && gpu.g >= 0.0f && gpu.b >= 0.0f);
      EXPECT_LE(glm::length(glm::vec3(shaded->at(x, y)) - glm::vec3(direct->at(x, y)) - gpu),
                1e-5f * (1.0f + glm::length(glm::vec3(shaded->at(x, y)))));
      ++checked;
      if (glm::length(expected) > 1e-2) ++lit;
    }
  EXPECT_GE(checked, 200);
  // By index range with K = 4, sender 0's last quarter is its rows below θ = 3π/4: all exposure 0.
  EXPECT_EQ(unexposed_lights, per_sender == 4 && !by_group ? 1 : 0);
  EXPECT_GE(lit, 100) << "the samples must include receivers lit by the lights";
}

INSTANTIATE_TEST_SUITE_P(PerSender, VsglPassLights,
                         ::testing::Combine(::testing::Values(1, 4),
                                            ::testing::Values(settings::VsglGrouping::vertex_ranges,
                                                              settings::VsglGrouping::bone_groups)));

// The CPU twin of rsm.vert/.frag: each texel's centre ray (sh::RsmView) against every sender
// triangle, the hit nearest the sun kept, position and normal interpolated linearly (the map is
// orthographic). light[i]: the light of sender i.
struct CpuTexel {
  sh::RsmTexel texel;
  int light = -1;
};
std::vector<CpuTexel> cpu_sun_map(const sh::RsmView& view, std::span<const Mesh> senders) {
  std::vector<CpuTexel> map;
  for (int y = 0; y < view.size; ++y)
    for (int x = 0; x < view.size; ++x) {
      const double u = view.u_min + (x + 0.5) * view.u_extent / view.size;
      const double v = view.v_min + (y + 0.5) * view.v_extent / view.size;
      const glm::dvec3 origin = u * view.right + v * view.up + view.s_max * view.toward_sun, along = -view.toward_sun;
      double nearest = 1e300;
      CpuTexel best;
      for (std::size_t m = 0; m < senders.size(); ++m) {
        const Mesh& mesh = senders[m];
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {  // Möller–Trumbore
          const glm::dvec3 p0(mesh.positions[mesh.indices[t]]), p1(mesh.positions[mesh.indices[t + 1]]),
              p2(mesh.positions[mesh.indices[t + 2]]);
          const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0, q = glm::cross(along, e2);
          const double det = glm::dot(e1, q);
          if (std::abs(det) < 1e-14) continue;
          const glm::dvec3 r = origin - p0;
          const double b1 = glm::dot(r, q) / det;
          const glm::dvec3 w = glm::cross(r, e1);
          const double b2 = glm::dot(along, w) / det, distance = glm::dot(e2, w) / det;
          if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 || distance >= nearest) continue;
          nearest = distance;
          const double b0 = 1.0 - b1 - b2;
          best.texel.position = b0 * p0 + b1 * p1 + b2 * p2;
          best.texel.normal = glm::normalize(b0 * glm::dvec3(mesh.normals[mesh.indices[t]]) +
                                             b1 * glm::dvec3(mesh.normals[mesh.indices[t + 1]]) +
                                             b2 * glm::dvec3(mesh.normals[mesh.indices[t + 2]]));
          best.texel.albedo = glm::dvec3(glm::vec3(mesh.albedo));
          best.light = int(m);
        }
      }
      if (best.light >= 0) map.push_back(best);
    }
  return map;
}

TEST_F(VsglPassTest, SunMapLightsAndIrradianceMatchTheCpuTwin) {
  // render.vsgl_sun auto with a sun above the horizon: the senders' vertex VPLs lit by L̃ without
  // the sun, plus the sun map's texels (the small sphere shadows part of the big one), per light.
  FrameConfig config;
  config.width = config.height = 64;
  config.frames_in_flight = 1;
  config.render.receiver_scale = 2;
  config.render.indirect_method = settings::IndirectMethod::vsgl;
  sh::AnalyticSky sun_sky;
  sun_sky.sun_direction = glm::normalize(glm::dvec3(0.6, 0.7, 0.3));
  sun_sky.sun_radius_radians = 0.05;
  sun_sky.sun_radiance = glm::dvec3(3000.0, 2800.0, 2400.0);  // E_s ≈ 23: a sunny day against sky()
  render::SunInput sun;
  sun.present = true;
  sun.lighting = sh::project_sun_disc(4, sun_sky);
  sun.direction = glm::vec3(sun_sky.sun_direction);
  sun.irradiance = glm::vec3(sun_sky.sun_radiance * (std::numbers::pi * std::pow(std::sin(sun_sky.sun_radius_radians), 2)));
  sh::RgbSh lighting = sky();
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < 16; ++i) lighting.channels[std::size_t(c)][i] += sun.lighting.channels[std::size_t(c)][i];
  const render::FrameTables tables = render::make_frame_tables(lighting, config.render, {}, {}, sun);
  ASSERT_TRUE(tables.vsgl_sun);
  const testing::GroundMesh ground = testing::ground_plane(20.0f, 4);
  const Mesh senders[] = {uv_sphere({0.0f, 0.6f, 0.0f}, 0.5f, 20, 24, {0.9f, 0.2f, 0.1f, 1.0f}),
                          uv_sphere({0.7f, 1.1f, 0.4f}, 0.25f, 12, 16, {0.1f, 0.3f, 0.9f, 1.0f})};
  std::vector<StaticMesh> meshes;
  auto ground_mesh = upload_static_mesh(context(), ground.positions, ground.normals, ground.indices, glm::vec4(0.8f));
  ASSERT_TRUE(ground_mesh.ok());
  meshes.push_back(std::move(*ground_mesh));
  for (const Mesh& sender : senders) {
    auto uploaded = upload_static_mesh(context(), sender.positions, sender.normals, sender.indices, sender.albedo);
    ASSERT_TRUE(uploaded.ok());
    meshes.push_back(std::move(*uploaded));
  }
  std::vector<DrawItem> draws;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    draws.push_back(meshes[i].draw());
    draws.back().vsgl_light = int(i) - 1;
  }
  // The proxies the map is fitted to: one sphere per sender.
  const std::vector<render::Sphere> spheres = {{{0.0f, 0.6f, 0.0f}, 0.5f, glm::vec3(0.5f)},
                                               {{0.7f, 1.1f, 0.4f}, 0.25f, glm::vec3(0.5f)}};
  auto frame = SoftGiFrame::create(context(), config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  ASSERT_TRUE(frame.ok()) << frame.message();
  ASSERT_TRUE((*frame)->write_slot(0, testing::look_at({0.5f, 3.0f, 4.0f}, {0.3f, 0.3f, 0.0f}, 60.0f, 1.0f), spheres).ok());
  ASSERT_TRUE(context()
                  .submit_and_wait([&](VkCommandBuffer commands) {
                    (*frame)->record(commands, 0, draws, FrameOutput::readback());
                  })
                  .ok());
  auto lights = (*frame)->read_vsgl_lights();
  ASSERT_TRUE(lights.ok());
  ASSERT_EQ(lights->size(), 2u);

  glm::dvec3 low(1e300), high(-1e300);
  for (const render::Sphere& sphere : spheres) {
    low = glm::min(low, glm::dvec3(sphere.center) - double(sphere.radius));
    high = glm::max(high, glm::dvec3(sphere.center) + double(sphere.radius));
  }
  const sh::RsmView view =
      sh::fit_rsm_view(sun_sky.sun_direction, low, high, int(gpu_layout::kRsmSize), sh::rsm_margin(low, high));
  const std::vector<CpuTexel> map = cpu_sun_map(view, senders);
  const sh::SunLight sun_light{sun_sky.sun_direction, glm::dvec3(sun.irradiance)};
  std::vector<sh::Vsgl> cpu;
  double sun_fraction[2] = {0.0, 0.0};
  for (std::size_t k = 0; k < 2; ++k) {
    const Mesh& mesh = senders[k];
    const glm::dvec3 origin(mesh.positions[0]);
    sh::VsglSums sums;
    add_cpu_sums(sums, origin, mesh, mesh.indices, tables.vsgl_sender_order3, 0, mesh.indices.size() / 3);
    const double vertex_weight = sums.weight;
    std::vector<sh::RsmTexel> texels;
    for (const CpuTexel& texel : map)
      if (texel.light == int(k)) texels.push_back(texel.texel);
    sh::add_vsgl_sun(sums, texels, sun_light, view.texel_area(), origin);
    sun_fraction[k] = 1.0 - vertex_weight / sums.weight;
    const auto expected = sh::fit_vsgl(sums, origin);
    ASSERT_TRUE(expected);
    cpu.push_back(*expected);
    const gpu_layout::VsglLight& gpu = (*lights)[k];
    SCOPED_TRACE("light " + std::to_string(k));
    EXPECT_LE(glm::length(glm::dvec3(gpu.axis_sharpness) - expected->axis), 1e-3);
    EXPECT_NEAR(gpu.axis_sharpness.w, expected->sharpness, 1e-3 * expected->sharpness + 1e-6);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu.amplitude[c], expected->amplitude[c], 1e-3 * expected->amplitude[c]);
    EXPECT_LE(glm::length(glm::dvec3(gpu.mean_variance) - expected->mean), 1e-3);
    EXPECT_NEAR(gpu.mean_variance.w, expected->variance, 2e-3 * expected->variance);
  }
  // The sun is most of each light's power: the map is what the lights show.
  EXPECT_GT(sun_fraction[0], 0.5);
  EXPECT_GT(sun_fraction[1], 0.5);

  auto positions = (*frame)->read_receiver_positions();
  auto normals = (*frame)->read_receiver_normals();
  auto indirect = (*frame)->read_indirect();
  ASSERT_TRUE(positions.ok() && normals.ok() && indirect.ok());
  int checked = 0;
  for (int y = 0; y < positions->height; y += 2)
    for (int x = 0; x < positions->width; x += 2) {
      const glm::vec4 p = positions->at(x, y);
      if (p.w <= 0.0f) continue;
      const glm::dvec3 n(glm::vec3(normals->at(x, y)));
      glm::dvec3 expected(0.0);
      for (const sh::Vsgl& light : cpu) expected += sh::vsgl_irradiance(light, glm::dvec3(glm::vec3(p)), n);
      const glm::vec3 gpu(indirect->at(x, y));
      const float error = glm::length(gpu - glm::vec3(expected)) / std::max(float(glm::length(expected)), 1e-3f);
      EXPECT_LE(error, 2e-3f) << "at " << x << "," << y;
      ++checked;
    }
  EXPECT_GE(checked, 200);
}

}  // namespace
}  // namespace proxygi::gpu
