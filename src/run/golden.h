#pragma once
// Golden frames: a rendered RGBA8 frame against a stored PNG with Filament's cross-driver
// tolerance (rendering-notes §3.3): a pixel fails when any channel differs by more than
// `channel_threshold` codes, and at most `max_failing_fraction` of the pixels may fail.
#include <cstdint>
#include <filesystem>
#include <span>

#include "base/result.h"

namespace proxygi::run {

struct GoldenTolerance {
  int channel_threshold = 5;            // 8-bit codes
  double max_failing_fraction = 0.001;  // of all pixels
};

struct GoldenComparison {
  int failing_pixels = 0;   // pixels with a channel beyond the threshold
  int differing_pixels = 0; // pixels that differ at all (0: bit-identical)
  int largest_difference = 0;  // codes, over every channel
  int pixels = 0;
  bool passed = false;
};

// Compares RGBA8 sRGB bytes (width × height, row 0 on top; alpha ignored) with the PNG at
// `golden`. Errors: a missing or unreadable golden, or a size mismatch (naming both sizes).
Result<GoldenComparison> compare_with_golden(std::span<const std::uint8_t> rgba8, int width, int height,
                                             const std::filesystem::path& golden, const GoldenTolerance& tolerance = {});
// Writes the frame as the new golden (atomically).
Status write_golden(std::span<const std::uint8_t> rgba8, int width, int height, const std::filesystem::path& golden);

}  // namespace proxygi::run
