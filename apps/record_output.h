#pragma once
// The files `proxygi record` writes into its output folder, and the rule that makes it
// resumable: a frame is done when all of its requested files exist. Every file is written
// atomically (temporary + rename), so a frame file that exists is complete.
//
//   DIR/frame_00012.png                 sRGB 8-bit (the renderer's LDR bytes, unchanged)
//   DIR/frame_00012.exr                 linear float radiance (with --exr or scene format exr)
//   DIR/aov/frame_00012_<name>.exr      intermediate buffers (with --aov), see write_aovs
//   DIR/aov/frame_00012_proxies.png     the frame with each proxy sphere's outline
//   DIR/record.json                     the manifest: which scene, size and version made the folder
// A resumed run trusts the files of a folder only when its manifest names the same scene (hash of
// the scene as rendered, overrides applied) and size; --verify also decodes each existing frame.
#include <cstdint>
#include <optional>
#include <string>
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

// True when the frame's PNG (and EXR when `exr`, and every AOV file when `aov`) exist, i.e. a
// resumed run may skip it. `verify`: each of those files must also decode (a truncated or
// foreign file makes the frame not done, so it is rendered again).
bool frame_done(const std::filesystem::path& dir, int frame, bool exr, bool aov, bool verify = false);

// DIR/record.json: what made the folder.
struct RecordManifest {
  std::string scene_hash;  // rig_file.h content_hash of scene::to_json of the scene as rendered
  int width = 0, height = 0;
  std::string version;     // proxygi version that wrote it
};
std::filesystem::path manifest_file(const std::filesystem::path& dir);
// nullopt when the folder has no manifest; an error when it is not one proxygi wrote.
Result<std::optional<RecordManifest>> read_manifest(const std::filesystem::path& dir);
Status write_manifest(const std::filesystem::path& dir, const RecordManifest& manifest);
// Why a folder recorded as `found` cannot be resumed as `wanted` (different scene or size), or "".
std::string manifest_mismatch(const RecordManifest& found, const RecordManifest& wanted);
// True when DIR holds frame files (frame_*.png / .exr).
bool has_frame_files(const std::filesystem::path& dir);

// Removes the temporaries ("<name>.tmp-<pid>", base/atomic_file.h) that processes which no longer
// run left in `dir` (a killed run); those of live processes (a concurrent shard) are kept.
// Returns how many were removed.
int remove_stale_temporaries(const std::filesystem::path& dir);

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
