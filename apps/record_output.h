#pragma once
// The files `proxygi record` writes into its output folder, and the rule that makes it
// resumable: a frame is done when all of its requested files exist. Every file is written
// atomically (temporary + rename), so a frame file that exists is complete.
//
//   DIR/frame_00012.png                 sRGB 8-bit (the renderer's LDR bytes, unchanged)
//   DIR/frame_00012.exr                 linear float radiance (with --exr or scene format exr)
//   DIR/aov/frame_00012_<name>.exr      intermediate buffers (with --aov), see write_aovs
//   DIR/aov/frame_00012_proxies.png     the frame with each proxy sphere's outline
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "gpu/soft_gi_frame.h"
#include "image/image.h"
#include "render/shading.h"
#include "scene/camera.h"

namespace proxygi::app {

// DIR/frame_%05d.<extension>
std::filesystem::path frame_file(const std::filesystem::path& dir, int frame, std::string_view extension);
// DIR/aov/frame_%05d_<name>.<extension>
std::filesystem::path aov_file(const std::filesystem::path& dir, int frame, std::string_view name,
                               std::string_view extension);

// True when the frame's PNG (and EXR when `exr`, and its AOVs when `aov`) exist, i.e. a resumed
// run may skip it. The proxies overlay is the last AOV written, so it stands for all of them.
bool frame_done(const std::filesystem::path& dir, int frame, bool exr, bool aov);

// RGBA8 sRGB bytes (row 0 on top) as a linear image that image::write_png turns back into the
// same bytes (8-bit sRGB codes survive the round trip exactly).
image::ImageF ldr_to_linear(std::span<const std::uint8_t> rgba8, int width, int height);

// Writes the frame's PNG (and EXR when `exr`); each file atomically.
Status write_frame_files(const std::filesystem::path& dir, int frame, std::span<const std::uint8_t> ldr,
                         const image::ImageF& hdr, int width, int height, bool exr);

// Writes the intermediate buffers of the most recently completed frame (so render it
// synchronously first) into DIR/aov: receivers (xyz receiver positions, eye depth in a),
// occlusion_dc ((O_p)_0 in rgb), direct, indirect (rgb irradiance at receiver resolution),
// upsampled (display-resolution irradiance), and proxies.png: `final_frame` with the outline of
// every sphere of `spheres` projected through `camera`.
Status write_aovs(const std::filesystem::path& dir, int frame, const gpu::SoftGiFrame& frame_buffers,
                  const image::ImageF& final_frame, std::span<const render::Sphere> spheres,
                  const scene::CameraState& camera);

// Draws the projected outline of each sphere (its silhouette circle, approximated by the
// projection of the sphere's center and radius at its distance) onto `image`, in place.
void draw_sphere_outlines(image::ImageF& image, std::span<const render::Sphere> spheres,
                          const scene::CameraState& camera);

}  // namespace proxygi::app
