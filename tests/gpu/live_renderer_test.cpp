// The frame renderer driven live (issue "One frame renderer for live use"): every render setting
// changed in place gives the frame a renderer created with it gives, bit for bit; a scene time
// renders what the frame number renders (and today's goldens); a camera override renders that
// camera; a caller's image receives the readback's pixels; the GPU skins the world state's poses
// as the path tracer's CPU skinning does, and its one skin dispatch per model primitive for all
// instances gives the vertices one dispatch per character gives.
#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "gpu/scene_renderer.h"
#include "gpu/skin_pass.h"
#include "gpu/transfer.h"
#include "gpu_test_context.h"
#include "ref/scene_geometry.h"
#include "run/golden.h"
#include "scene/scene_defaults.h"
#include "settings/fields.h"

namespace proxygi::gpu {
namespace {

using LiveRendererTest = testing::GpuTest;

constexpr std::uint32_t kSize = 64;
constexpr int kFrame = 40;

std::shared_ptr<const world::World> default_world(scene::Scene scene = scene::default_scene()) {
  auto world = world::World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = true,
                                          .write_rig_cache = false});
  EXPECT_TRUE(world.ok()) << world.message();
  return world.ok() ? std::shared_ptr<const world::World>(std::move(*world)) : nullptr;
}

// A valid value of `field` other than the default's.
double other_value(const settings::Field& field, const settings::RenderSettings& defaults) {
  const double current = field.get(defaults);
  // A field with named values (render.quality: "manual" → "high") takes its last name.
  if (!field.named.empty() && field.named.back().value != current) return field.named.back().value;
  switch (field.kind) {
    case settings::FieldKind::boolean: return current != 0.0 ? 0.0 : 1.0;
    case settings::FieldKind::choice:
      for (const settings::Choice& choice : field.choices)
        if (double(choice.value) != current) return choice.value;
      break;
    case settings::FieldKind::integer:
      if (!field.allowed.empty()) {
        for (int allowed : field.allowed)
          if (double(allowed) > current) return allowed;
        return field.allowed.front();
      }
      return current + 1.0 <= field.max ? current + 1.0 : current - 1.0;
    case settings::FieldKind::real: return field.min_exclusive ? current * 1.5 : current + 1.0;
  }
  return current;
}

void expect_same_frame(const FinishedFrame& a, const FinishedFrame& b, const std::string& what) {
  ASSERT_EQ(a.ldr.size(), b.ldr.size()) << what;
  EXPECT_TRUE(a.ldr == b.ldr) << what << ": sRGB frames differ";
  ASSERT_EQ(a.hdr.pixels.size(), b.hdr.pixels.size()) << what;
  EXPECT_EQ(std::memcmp(a.hdr.pixels.data(), b.hdr.pixels.data(), a.hdr.pixels.size() * sizeof(glm::vec4)), 0)
      << what << ": HDR frames differ";
}

TEST_F(LiveRendererTest, EveryFieldChangedInPlaceMatchesAFreshRenderer) {
  auto world = default_world();
  ASSERT_TRUE(world);
  const settings::RenderSettings defaults = world->scene().render;
  auto live = SceneRenderer::create(context(), world, defaults, kSize, kSize);
  ASSERT_TRUE(live.ok()) << live.message();
  auto first = (*live)->render(kFrame);
  ASSERT_TRUE(first.ok()) << first.message();
  for (const settings::Field& field : settings::fields()) {
    settings::RenderSettings changed = defaults;
    field.set(changed, other_value(field, defaults));
    ASSERT_NE(settings::classify_change(defaults, changed), settings::kNeedNothing) << field.key;
    const std::string what = "render." + std::string(field.key) + " changed in place";
    ASSERT_TRUE((*live)->apply_settings(changed, kSize, kSize).ok()) << what;
    auto in_place = (*live)->render(kFrame);
    ASSERT_TRUE(in_place.ok()) << in_place.message();
    auto fresh = SceneRenderer::create(context(), world, changed, kSize, kSize);
    ASSERT_TRUE(fresh.ok()) << fresh.message();
    auto expected = (*fresh)->render(kFrame);
    ASSERT_TRUE(expected.ok()) << expected.message();
    expect_same_frame(*in_place, *expected, what);
    // And back: the defaults again give the first frame.
    ASSERT_TRUE((*live)->apply_settings(defaults, kSize, kSize).ok()) << what;
    auto back = (*live)->render(kFrame);
    ASSERT_TRUE(back.ok()) << back.message();
    expect_same_frame(*back, *first, what + " and back");
  }
  // The output size changes in place too.
  ASSERT_TRUE((*live)->apply_settings(defaults, 48, 40).ok());
  auto resized = (*live)->render(kFrame);
  ASSERT_TRUE(resized.ok()) << resized.message();
  auto fresh = SceneRenderer::create(context(), world, defaults, 48, 40);
  ASSERT_TRUE(fresh.ok()) << fresh.message();
  auto expected = (*fresh)->render(kFrame);
  ASSERT_TRUE(expected.ok()) << expected.message();
  expect_same_frame(*resized, *expected, "output 48x40 in place");
}

// The VSGL sender exposure (Embree, about a second per model) is computed only where VSGL needs
// it: not for a renderer created with indirect_method proxy; on a live switch to vsgl once per
// model, not per instance (the crowd's 20 characters share one model), and not again when
// switched back and forth; the switched renderer renders what one created with vsgl renders.
TEST_F(LiveRendererTest, SenderExposureIsComputedOnFirstVsglUseOncePerModel) {
  auto world = default_world(scene::crowd_scene());
  ASSERT_TRUE(world);
  ASSERT_GT(world->instances().size(), world->models().size()) << "the crowd's characters share a model";
  settings::RenderSettings proxy = world->scene().render;
  proxy.indirect_method = settings::IndirectMethod::proxy;
  settings::RenderSettings vsgl = proxy;
  vsgl.indirect_method = settings::IndirectMethod::vsgl;
  auto live = SceneRenderer::create(context(), world, proxy, kSize, kSize);
  ASSERT_TRUE(live.ok()) << live.message();
  ASSERT_TRUE((*live)->render(kFrame).ok());
  EXPECT_EQ((*live)->sender_exposure_computations(), 0u) << "indirect_method proxy needs no sender exposure";

  ASSERT_TRUE((*live)->apply_settings(vsgl, kSize, kSize).ok());
  EXPECT_EQ((*live)->sender_exposure_computations(), world->models().size());
  auto switched = (*live)->render(kFrame);
  ASSERT_TRUE(switched.ok()) << switched.message();
  auto fresh = SceneRenderer::create(context(), world, vsgl, kSize, kSize);
  ASSERT_TRUE(fresh.ok()) << fresh.message();
  EXPECT_EQ((*fresh)->sender_exposure_computations(), world->models().size());
  auto expected = (*fresh)->render(kFrame);
  ASSERT_TRUE(expected.ok()) << expected.message();
  expect_same_frame(*switched, *expected, "indirect_method vsgl switched in place");

  ASSERT_TRUE((*live)->apply_settings(proxy, kSize, kSize).ok());
  ASSERT_TRUE((*live)->render(kFrame).ok());
  ASSERT_TRUE((*live)->apply_settings(vsgl, kSize, kSize).ok());
  auto again = (*live)->render(kFrame);
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ((*live)->sender_exposure_computations(), world->models().size()) << "kept, not recomputed";
  expect_same_frame(*again, *expected, "indirect_method vsgl after proxy and back");
}

// Only the target buffers upsample_composite.comp reads as texels (its receivers and shaded
// bindings) have uniform texel usage, each with its view; the other targets have neither
// (frame_resources.cpp keeps the one list). With and without supersampling (its sample targets).
TEST_F(LiveRendererTest, TexelUsageOnlyOnTheTargetsReadAsTexels) {
  auto world = default_world();
  ASSERT_TRUE(world);
  settings::RenderSettings supersampled = world->scene().render;
  supersampled.antialiasing = settings::Antialiasing::ssaa2;
  auto renderer = SceneRenderer::create(context(), world, world->scene().render, kSize, kSize);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  for (const settings::RenderSettings& render : {world->scene().render, supersampled}) {
    ASSERT_TRUE((*renderer)->apply_settings(render, kSize, kSize).ok());
    std::vector<std::string> texel_targets;
    std::vector<std::string> allocated;
    for (const SoftGiFrame::TargetBufferInfo& target : (*renderer)->frame().target_buffers()) {
      if (target.buffer->handle() == VK_NULL_HANDLE) continue;  // unused by this configuration
      allocated.emplace_back(target.name);
      const bool texel_usage = (target.buffer->usage() & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT) != 0;
      EXPECT_EQ(texel_usage, target.texels) << target.name;
      EXPECT_EQ(target.buffer->texel_view() != VK_NULL_HANDLE, target.texels) << target.name;
      if (target.texels) texel_targets.emplace_back(target.name);
    }
    EXPECT_EQ(texel_targets, (std::vector<std::string>{"receivers", "shaded"}));
    const bool samples = std::find(allocated.begin(), allocated.end(), "sample_hdr") != allocated.end();
    EXPECT_EQ(samples, render.antialiasing != settings::Antialiasing::off) << "the sample targets were checked";
    ASSERT_TRUE((*renderer)->render(kFrame).ok());
  }
}

TEST_F(LiveRendererTest, SceneTimeRendersTheFrameAndItsGolden) {
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = 256;
  auto world = default_world(scene);
  ASSERT_TRUE(world);
  auto renderer = SceneRenderer::create(context(), world, scene.render, 256, 256);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const bool reference_driver = context().report().name.find("llvmpipe") != std::string::npos;
  for (int frame : {0, 40, 90}) {
    FrameRequest request;
    request.time_s = double(frame) / scene.output.fps;
    auto by_time = (*renderer)->render(request);
    ASSERT_TRUE(by_time.ok()) << by_time.message();
    auto by_frame = (*renderer)->render(frame);
    ASSERT_TRUE(by_frame.ok()) << by_frame.message();
    expect_same_frame(*by_time, *by_frame, "frame " + std::to_string(frame));
    auto golden = run::compare_with_golden(by_time->ldr, 256, 256,
                                           PROXYGI_SOURCE_DIR "/tests/regress/goldens/golden_default_256/llvmpipe/frame/frame_000" +
                                               std::string(frame < 10 ? "0" : "") + std::to_string(frame) + ".png");
    ASSERT_TRUE(golden.ok()) << golden.message();
    EXPECT_TRUE(golden->passed) << golden->failing_pixels << " pixels beyond 5/255";
    if (reference_driver) {
      EXPECT_EQ(golden->differing_pixels, 0) << "the goldens were made on lavapipe: bit-identical";
    }
  }
}

TEST_F(LiveRendererTest, CameraOverrideRendersThatCamera) {
  const scene::CameraState camera{{2.5f, 1.8f, 3.0f}, {0.0f, 0.9f, 0.0f}, {0, 1, 0}, 40.0f, 0.05f, 200.0f};
  scene::Scene fixed = scene::default_scene();
  fixed.camera.kind = scene::FixedCamera{camera.eye, camera.target, camera.up, camera.fov_y_degrees};
  fixed.camera.near_m = camera.near_m;
  fixed.camera.far_m = camera.far_m;
  auto world = default_world();
  auto fixed_world = default_world(fixed);
  ASSERT_TRUE(world && fixed_world);
  auto renderer = SceneRenderer::create(context(), world, world->scene().render, kSize, kSize);
  auto fixed_renderer = SceneRenderer::create(context(), fixed_world, fixed.render, kSize, kSize);
  ASSERT_TRUE(renderer.ok() && fixed_renderer.ok());
  FrameRequest request;
  request.time_s = double(kFrame) / fixed.output.fps;
  request.camera = camera;
  auto overridden = (*renderer)->render(request);
  auto expected = (*fixed_renderer)->render(kFrame);
  auto scene_camera = (*renderer)->render(kFrame);
  ASSERT_TRUE(overridden.ok() && expected.ok() && scene_camera.ok());
  expect_same_frame(*overridden, *expected, "camera override");
  EXPECT_FALSE(overridden->ldr == scene_camera->ldr) << "the override must not render the scene's own camera";
}

// The frame through a caller's image of `format`, read back as RGBA8 bytes.
std::vector<std::uint8_t> render_into_image(Context& context, SceneRenderer& renderer, VkFormat format,
                                            std::uint32_t width, std::uint32_t height) {
  auto image = Image::create(context, width, height, format,
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  EXPECT_TRUE(image.ok()) << image.message();
  if (!image.ok()) return {};
  FrameRequest request;
  request.time_s = double(kFrame) / renderer.scene().output.fps;
  request.output = FrameOutput::into({image->handle(), format, width, height, VK_IMAGE_LAYOUT_UNDEFINED,
                                      VK_IMAGE_LAYOUT_GENERAL});
  auto rendered = renderer.render(request);
  EXPECT_TRUE(rendered.ok()) << rendered.message();
  EXPECT_TRUE(rendered.ok() && rendered->ldr.empty()) << "an image output reads nothing back";
  auto bytes = readback(context, *image, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_TRUE(bytes.ok());
  if (!bytes.ok()) return {};
  if (format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB)
    for (std::size_t i = 0; i + 3 < bytes->size(); i += 4) std::swap((*bytes)[i], (*bytes)[i + 2]);
  return *bytes;
}

TEST_F(LiveRendererTest, CallerImageGetsTheReadbackPixels) {
  auto world = default_world();
  ASSERT_TRUE(world);
  auto renderer = SceneRenderer::create(context(), world, world->scene().render, kSize, kSize);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  auto readback_frame = (*renderer)->render(kFrame);
  ASSERT_TRUE(readback_frame.ok());
  for (VkFormat format : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM,
                          VK_FORMAT_B8G8R8A8_SRGB}) {
    const auto pixels = render_into_image(context(), **renderer, format, kSize, kSize);
    EXPECT_TRUE(pixels == readback_frame->ldr) << "format " << int(format);
  }
  // A smaller image gets a filtered copy: its mean stays the frame's within a code. B8G8R8A8 too
  // (the composite writes that order, a staging image of it is blitted: a scaled window).
  for (VkFormat format : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM}) {
    const auto half = render_into_image(context(), **renderer, format, kSize / 2, kSize / 2);
    ASSERT_EQ(half.size(), std::size_t(kSize / 2) * (kSize / 2) * 4);
    for (int c = 0; c < 3; ++c) {
      double full_mean = 0, half_mean = 0;
      for (std::size_t i = std::size_t(c); i < readback_frame->ldr.size(); i += 4) full_mean += readback_frame->ldr[i];
      for (std::size_t i = std::size_t(c); i < half.size(); i += 4) half_mean += half[i];
      EXPECT_NEAR(full_mean / (kSize * kSize), half_mean / (kSize * kSize / 4), 1.5)
          << "format " << int(format) << " channel " << c;
    }
  }
  FrameRequest bad;
  bad.output = FrameOutput::into({VK_NULL_HANDLE, VK_FORMAT_R32_SFLOAT, kSize, kSize});
  EXPECT_FALSE((*renderer)->render(bad).ok());
}

// The path tracer and the GPU renderer pose the same scene identically: from one shared world
// state, the GPU's skinned vertices equal the path tracer's meshes (ref::world_meshes, CPU
// skinning) within 2e-5 m (1e-5 of the 1.8 m figure) at several times.
TEST_F(LiveRendererTest, GpuAndPathTracerPoseTheWorldStateAlike) {
  auto world = default_world(scene::crowd_scene());
  ASSERT_TRUE(world);
  auto renderer = SceneRenderer::create(context(), world, world->scene().render, kSize, kSize);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const ref::SceneGeometry geometry = ref::make_scene_geometry(*world);
  world::WorldState state;
  for (double t : {0.0, 0.7, 2.35}) {
    ASSERT_TRUE(world->evaluate(t, std::nullopt, state).ok());
    FrameRequest request;
    request.state = &state;
    ASSERT_TRUE((*renderer)->render(request).ok());
    auto gpu = (*renderer)->read_skinned_positions();
    ASSERT_TRUE(gpu.ok()) << gpu.message();
    auto traced = ref::world_meshes(*world, state, geometry);
    ASSERT_TRUE(traced.ok()) << traced.message();
    // The path tracer's meshes: the ground, then each character's primitives in instance order.
    std::size_t mesh = world->scene().ground.enabled ? 1 : 0;
    ASSERT_EQ(gpu->size(), world->instances().size());
    for (std::size_t i = 0; i < gpu->size(); ++i)
      for (std::size_t p = 0; p < (*gpu)[i].size(); ++p, ++mesh) {
        ASSERT_LT(mesh, traced->size());
        const auto& expected = (*traced)[mesh].positions;
        ASSERT_EQ((*gpu)[i][p].size(), expected.size()) << "instance " << i << " primitive " << p;
        float largest = 0.0f;
        for (std::size_t v = 0; v < expected.size(); ++v)
          largest = std::max(largest, glm::length((*gpu)[i][p][v] - expected[v]));
        EXPECT_LT(largest, 2e-5f) << "t " << t << " instance " << i << " primitive " << p;
      }
    EXPECT_EQ(mesh, traced->size() - world->static_models().size()) << "every character mesh compared";
  }
}

// The crowd's 20 mannequins skinned in one dispatch per primitive (SkinBatch) give bit for bit
// the vertices of skinning each character in a dispatch of its own (the per-character path the
// renderer used before), at several times.
TEST_F(LiveRendererTest, CrowdSkinnedInOneDispatchPerPrimitiveEqualsOneDispatchPerCharacter) {
  auto world = default_world(scene::crowd_scene());
  ASSERT_TRUE(world);
  ASSERT_GE(world->instances().size(), 20u);
  auto renderer = SceneRenderer::create(context(), world, world->scene().render, kSize, kSize);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  auto pass = SkinPass::create(context());
  ASSERT_TRUE(pass.ok()) << pass.message();
  world::WorldState state;
  for (double t : {0.0, 1.3}) {
    ASSERT_TRUE(world->evaluate(t, std::nullopt, state).ok());
    FrameRequest request;
    request.state = &state;
    ASSERT_TRUE((*renderer)->render(request).ok());
    auto batched = (*renderer)->read_skinned_positions();
    ASSERT_TRUE(batched.ok()) << batched.message();
    ASSERT_EQ(batched->size(), world->instances().size());
    std::size_t compared = 0;
    for (std::size_t i = 0; i < world->instances().size(); ++i) {
      const anim::Character& character = world->instances()[i].model->character;
      const anim::PoseBuffers& pose = state.instances[i].pose;
      std::size_t p = 0;  // primitive of the instance, in read_skinned_positions order
      for (const anim::Node& node : character.nodes) {
        if (node.mesh < 0) continue;
        ASSERT_GE(node.skin, 0) << "the crowd's meshes are skinned";
        const auto& palette = pose.skin_matrices[std::size_t(node.skin)];
        const auto& normals = pose.normal_matrices[std::size_t(node.skin)];
        Buffer palettes[2];
        for (int b = 0; b < 2; ++b) {
          const auto& matrices = b == 0 ? palette : normals;
          auto buffer = create_buffer_with_data(context(), as_bytes(std::span<const glm::mat4>(matrices)),
                                                SkinPass::kPaletteUsage);
          ASSERT_TRUE(buffer.ok()) << buffer.message();
          palettes[b] = std::move(*buffer);
        }
        for (const anim::Primitive& primitive : character.meshes[std::size_t(node.mesh)].primitives) {
          auto single = SkinPass::upload(context(), primitive);
          ASSERT_TRUE(single.ok()) << single.message();
          ASSERT_TRUE(context()
                          .submit_and_wait([&](VkCommandBuffer commands) {
                            pass->record(context(), commands, *single,
                                         SkinPalette{&palettes[0], &palettes[1], std::uint32_t(palette.size())});
                            SkinPass::record_outputs_barrier(commands);
                          })
                          .ok());
          auto bytes = readback(context(), single->world_positions);
          ASSERT_TRUE(bytes.ok()) << bytes.message();
          ASSERT_LT(p, (*batched)[i].size());
          const std::vector<glm::vec3>& got = (*batched)[i][p++];
          ASSERT_EQ(got.size(), primitive.positions.size()) << "instance " << i;
          const auto* expected = reinterpret_cast<const glm::vec4*>(bytes->data());
          std::size_t differing = 0;
          for (std::size_t v = 0; v < got.size(); ++v)
            if (std::memcmp(&got[v], &expected[v], sizeof(glm::vec3)) != 0) ++differing;
          EXPECT_EQ(differing, 0u) << "t " << t << " instance " << i << " primitive " << p - 1;
          ++compared;
        }
      }
      EXPECT_EQ(p, (*batched)[i].size()) << "every primitive of instance " << i << " compared";
    }
    EXPECT_GE(compared, 80u);
  }
}

}  // namespace
}  // namespace proxygi::gpu
