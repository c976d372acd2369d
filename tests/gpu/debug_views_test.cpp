// The viewer's views of the composite pass (layouts.h kDebugView*) against the frame's own
// components and their CPU twins: direct + indirect = the final frame before the tonemap, the
// direct and occlusion views are the receivers' E_direct and visibility DC upsampled with
// eq. 11 (render::upsample), occlusion lies in [0, 1], and the heat map's count at each tile is
// the CPU count of the spheres whose influence η·r reaches the tile's bounding sphere.
#include <cmath>
#include <map>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/shading.h"
#include "upsample_taps.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

using DebugViewsTest = testing::GpuTest;
using namespace gpu_layout;
constexpr float kPi = 3.14159265358979f;
constexpr int kSize = 64;

// One fixture frame (ground plane under a white sky, `spheres` above it) rendered once per view;
// the HDR output of each view, and the frame (its targets hold the last view's frame, which
// every view shares up to the composite).
struct Views {
  std::unique_ptr<SoftGiFrame> frame;
  std::map<std::uint32_t, image::ImageF> hdr;
  std::map<std::uint32_t, std::vector<std::uint8_t>> ldr;
};

Views render_views(Context& context, FrameConfig config, const std::vector<render::Sphere>& spheres,
                   std::initializer_list<std::uint32_t> views) {
  Views out;
  config.width = config.height = kSize;
  config.frames_in_flight = 1;
  const render::FrameTables tables = render::make_frame_tables(testing::constant_sky_sh(config.render.sh_order, 1.0), config.render);
  const testing::GroundMesh ground = testing::ground_plane(20.0f, 4);
  auto mesh = upload_static_mesh(context, ground.positions, ground.normals, ground.indices, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  EXPECT_TRUE(mesh.ok());
  if (!mesh.ok()) return out;
  const DrawItem draws[] = {mesh->draw()};
  auto frame = SoftGiFrame::create(context, config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  EXPECT_TRUE(frame.ok()) << (frame.ok() ? "" : frame.message());
  if (!frame.ok()) return out;
  out.frame = std::move(*frame);
  for (std::uint32_t view : views) {
    FrameView camera = testing::look_at({0.0f, 4.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f);
    camera.debug_view = view;
    EXPECT_TRUE(out.frame->write_slot(0, camera, spheres).ok());
    EXPECT_TRUE(context.submit_and_wait([&](VkCommandBuffer c) { out.frame->record(c, 0, draws, FrameOutput::readback()); }).ok());
    auto hdr = out.frame->read_hdr();
    auto ldr = out.frame->read_ldr();
    EXPECT_TRUE(hdr.ok() && ldr.ok());
    if (hdr.ok()) out.hdr[view] = std::move(*hdr);
    if (ldr.ok()) out.ldr[view] = std::move(*ldr);
  }
  return out;
}

float relative_error(const glm::vec3& gpu, const glm::vec3& cpu) {
  return glm::length(gpu - cpu) / std::max(glm::length(cpu), 1e-3f);
}

// The CPU twin of the composite's upsampling of a receiver quantity at display pixel (x, y).
glm::vec3 upsample_at(int x, int y, int scale, const image::ImageF& values, const image::ImageF& receiver_positions,
                      const image::ImageF& receiver_normals, const image::ImageF& gbuffer_positions,
                      const image::ImageF& gbuffer_normals, const std::function<glm::vec3(const glm::vec4&)>& pick) {
  const auto taps = testing::upsample_taps(
      x, y, scale, kSize / scale, [&](int rx, int ry) { return pick(values.at(rx, ry)); }, receiver_positions,
      receiver_positions, receiver_normals);
  return render::upsample(taps, glm::vec3(gbuffer_positions.at(x, y)), gbuffer_positions.at(x, y).w, glm::vec3(gbuffer_normals.at(x, y)),
                          settings::Upsampling::bilateral, settings::RenderSettings{}.bilateral_depth_epsilon);
}

TEST_F(DebugViewsTest, DirectIndirectAndOcclusionAreTheFinalFramesComponents) {
  const std::vector<render::Sphere> spheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}},
                                               {{0.7f, 0.3f, 0.4f}, 0.3f, {0.1f, 0.2f, 0.9f}}};
  for (const settings::ShadingMethod method : {settings::ShadingMethod::image_space, settings::ShadingMethod::ambient_occlusion}) {
    SCOPED_TRACE(std::string(settings::name_of(method)));
    FrameConfig config;
    config.render.method = method;
    config.render.receiver_scale = 2;
    const Views views = render_views(context(), config, spheres,
                                     {kDebugViewFinal, kDebugViewDirect, kDebugViewIndirect, kDebugViewOcclusion});
    ASSERT_TRUE(views.frame);
    ASSERT_EQ(views.hdr.size(), 4u);
    auto positions = views.frame->read_gbuffer_positions();
    auto normals = views.frame->read_gbuffer_normals();
    auto albedo = views.frame->read_gbuffer_albedo();
    auto direct = views.frame->read_direct();
    auto indirect = views.frame->read_indirect();
    auto shaded = views.frame->read_shaded();
    auto receiver_normals = views.frame->read_receiver_normals();
    auto receiver_positions = views.frame->read_receiver_positions();
    ASSERT_TRUE(positions.ok() && normals.ok() && albedo.ok() && direct.ok() && indirect.ok() && shaded.ok() &&
                receiver_normals.ok() && receiver_positions.ok());
    const float occlusion_scale = method == settings::ShadingMethod::ambient_occlusion ? 1.0f : 1.0f / std::sqrt(4.0f * kPi);
    const image::ImageF& final_hdr = views.hdr.at(kDebugViewFinal);
    int covered = 0, shadowed = 0, open = 0, bounced = 0;
    for (int y = 0; y < kSize; y += 2)
      for (int x = 0; x < kSize; x += 2) {
        const glm::vec3 final_radiance(final_hdr.at(x, y));
        const glm::vec3 direct_view(views.hdr.at(kDebugViewDirect).at(x, y));
        const glm::vec3 indirect_view(views.hdr.at(kDebugViewIndirect).at(x, y));
        const glm::vec3 occlusion(views.hdr.at(kDebugViewOcclusion).at(x, y));
        if (positions->at(x, y).w <= 0.0f) {  // the background is the environment in every view
          EXPECT_EQ(direct_view, final_radiance);
          EXPECT_EQ(occlusion, final_radiance);
          continue;
        }
        ++covered;
        EXPECT_LE(relative_error(direct_view + indirect_view, final_radiance), 1e-4f) << "direct + indirect at " << x << "," << y;
        const glm::vec3 surface = glm::vec3(albedo->at(x, y)) / kPi;
        auto rgb = [](const glm::vec4& v) { return glm::vec3(v); };
        const glm::vec3 expected_direct = surface * upsample_at(x, y, 2, *direct, *receiver_positions, *receiver_normals, *positions, *normals, rgb);
        EXPECT_LE(relative_error(direct_view, expected_direct), 1e-3f) << "direct at " << x << "," << y;
        const glm::vec3 expected_indirect = surface * upsample_at(x, y, 2, *indirect, *receiver_positions, *receiver_normals, *positions, *normals, rgb);
        EXPECT_LE(glm::length(indirect_view - expected_indirect), 1e-3f * std::max(glm::length(final_radiance), 1e-3f))
            << "indirect at " << x << "," << y;
        const float expected_visible = std::clamp(
            upsample_at(x, y, 2, *direct, *receiver_positions, *receiver_normals, *positions, *normals,
                        [&](const glm::vec4& v) { return glm::vec3(v.w * occlusion_scale); }).x, 0.0f, 1.0f);
        EXPECT_NEAR(occlusion.x, expected_visible, 1e-4f) << "occlusion at " << x << "," << y;
        EXPECT_GE(occlusion.x, 0.0f);
        EXPECT_LE(occlusion.x, 1.0f);
        EXPECT_EQ(occlusion.x, occlusion.y);
        shadowed += occlusion.x < 0.8f;
        open += occlusion.x > 0.99f;
        bounced += glm::length(indirect_view) > 1e-4f;
      }
    EXPECT_GE(covered, 200);
    EXPECT_GT(shadowed, 4) << "the spheres occlude the plane under them";
    EXPECT_GT(open, 20) << "the plane far from them is unoccluded";
    if (method == settings::ShadingMethod::image_space) EXPECT_GT(bounced, 4) << "bounce light near the spheres";
    else EXPECT_EQ(bounced, 0) << "AO has no bounce light";
  }
}

TEST_F(DebugViewsTest, HeatMapCountsTheProxiesEachTileKeeps) {
  // Small spheres spread over the plane: tiles differ in how many reach them (η·r = 0.75–1.5 m).
  std::vector<render::Sphere> spheres;
  for (int i = 0; i < 7; ++i)
    spheres.push_back({{-3.0f + float(i), 0.3f, -1.5f + 0.5f * float(i % 3)}, 0.05f + 0.01f * float(i), {0.5f, 0.5f, 0.5f}});
  for (const settings::ShadingMethod method : {settings::ShadingMethod::image_space, settings::ShadingMethod::ambient_occlusion}) {
    SCOPED_TRACE(std::string(settings::name_of(method)));
    FrameConfig config;
    config.render.method = method;
    config.render.receiver_scale = 1;  // 64×64 receivers: 8×8 tiles of 8×8 pixels
    const Views views = render_views(context(), config, spheres, {kDebugViewFinal, kDebugViewHeatMap});
    ASSERT_TRUE(views.frame);
    auto counts = views.frame->read_tile_counts();
    auto receivers = views.frame->read_receiver_positions();
    ASSERT_TRUE(counts.ok() && receivers.ok());
    const std::uint32_t tiles_x = views.frame->tiles_x(), tiles_y = views.frame->tiles_y();
    ASSERT_EQ(tiles_x, 8u);
    ASSERT_EQ(counts->size(), std::size_t(tiles_x) * tiles_y);
    const float eta = config.render.shadow_eta;
    int compared = 0, some = 0, fewer = 0;
    for (std::uint32_t ty = 0; ty < tiles_y; ++ty)
      for (std::uint32_t tx = 0; tx < tiles_x; ++tx) {
        glm::vec3 low(1e30f), high(-1e30f);
        for (std::uint32_t y = ty * 8; y < ty * 8 + 8; ++y)
          for (std::uint32_t x = tx * 8; x < tx * 8 + 8; ++x)
            if (receivers->at(int(x), int(y)).w > 0.0f)
              low = glm::min(low, glm::vec3(receivers->at(int(x), int(y)))), high = glm::max(high, glm::vec3(receivers->at(int(x), int(y))));
        std::uint32_t expected = 0;
        bool borderline = false;
        if (low.x <= high.x) {
          const glm::vec3 center = 0.5f * (low + high);
          const float radius = 0.5f * glm::length(high - low);
          for (const render::Sphere& sphere : spheres) {
            const float reach = eta * sphere.radius + radius, distance = glm::length(sphere.center - center);
            expected += distance < reach;
            borderline |= std::abs(distance - reach) < 1e-4f * reach;
          }
        }
        const std::uint32_t gpu = (*counts)[ty * tiles_x + tx];
        if (!borderline) {
          EXPECT_EQ(gpu, expected) << "tile " << tx << "," << ty;
          ++compared;
        }
        some += gpu > 0;
        fewer += gpu > 0 && gpu < spheres.size();
        // The view's HDR holds the count on every pixel of the tile; its display is tinted.
        for (std::uint32_t y = ty * 8; y < ty * 8 + 8; y += 3)
          for (std::uint32_t x = tx * 8; x < tx * 8 + 8; x += 3)
            EXPECT_EQ(views.hdr.at(kDebugViewHeatMap).at(int(x), int(y)), glm::vec4(glm::vec3(float(gpu)), 1.0f)) << x << "," << y;
        const std::size_t middle = (std::size_t(ty * 8 + 4) * kSize + tx * 8 + 4) * 4;
        if (gpu > 0) EXPECT_NE(views.ldr.at(kDebugViewHeatMap)[middle], views.ldr.at(kDebugViewFinal)[middle]) << tx << "," << ty;
        else EXPECT_EQ(views.ldr.at(kDebugViewHeatMap)[middle], views.ldr.at(kDebugViewFinal)[middle]) << tx << "," << ty;
      }
    EXPECT_GE(compared, 56);
    EXPECT_GT(some, 2);
    EXPECT_GT(fewer, 1);
  }
  // The raster splat keeps no tile lists: the heat-map view is the final frame.
  FrameConfig config;
  config.render.splat = settings::SplatMethod::raster;
  const Views raster = render_views(context(), config, spheres, {kDebugViewFinal, kDebugViewHeatMap});
  ASSERT_TRUE(raster.frame);
  EXPECT_EQ(raster.ldr.at(kDebugViewHeatMap), raster.ldr.at(kDebugViewFinal));
}

}  // namespace
}  // namespace proxygi::gpu
