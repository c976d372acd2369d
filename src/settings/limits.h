#pragma once
// The size limits every command applies, defined once: image size, frame count, samples per
// pixel and input file sizes. The scene file, the CLI options of record, reference, bench and
// view, the glTF importer and the image reader all read these, so one over-limit value is refused
// the same way everywhere (exit 2, with the bounds in the message).
#include <cstdint>
#include <cstdio>
#include <string>

namespace proxygi::settings {

inline constexpr int kMinImageSize = 16;    // pixels, width or height of a rendered image
inline constexpr int kMaxImageSize = 8192;  // pixels, width or height of any image read or rendered
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t(kMaxImageSize) * kMaxImageSize;  // width * height

inline constexpr int kMaxFrameCount = 1000000;  // frames of one scene (output.frames.count, record -f)

inline constexpr int kMaxSamplesPerPixel = 1 << 20;  // reference --spp, in one run and over all resumed runs

inline constexpr int kMaxProxySpheres = 4096;  // fit --max-spheres, characters[].proxy_max_spheres

inline constexpr std::uint64_t kMaxModelFileBytes = std::uint64_t(1) << 30;  // a glTF/GLB file and each file it names
inline constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(16) << 20;  // a scene or scenario JSON file

// "1073741824 bytes (1 GiB)": a byte count as a person reads it, for limit messages. Header-only
// so that libraries below settings (base, anim) can word their limits the same way.
inline std::string readable_bytes(std::uint64_t bytes) {
  const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
  std::string out = std::to_string(bytes) + " bytes";
  if (bytes < 1024) return out;
  double value = double(bytes);
  int unit = -1;
  while (value >= 1024.0 && unit < 3) value /= 1024.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, value == double(std::uint64_t(value)) ? " (%.0f %s)" : " (%.1f %s)", value, units[unit]);
  return out + text;
}

}  // namespace proxygi::settings
