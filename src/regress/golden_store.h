#pragma once
// Where goldens live: ROOT/<scenario>/<tier>/<check>/..., ROOT = the scenario folder's goldens/
// unless given. Tiers: the device family (device_family() of the Vulkan device name: llvmpipe,
// nvidia, amd, intel, apple, other), then the fallback tier "any", whose goldens are compared
// with each check's thresholds multiplied by its fallback_scale. Blessing writes the family tier.
// Files: frame_%05d.png (final frames, 8-bit sRGB), frame_%05d.exr (linear AOVs, 32-bit float),
// tracks.json (full precision, %.17g), temporal.json.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace proxygi::regress {

inline constexpr std::string_view kFallbackTier = "any";

std::string device_family(std::string_view device_name);

struct GoldenStore {
  std::filesystem::path root;
  std::string family;

  std::filesystem::path dir(const std::string& scenario, std::string_view tier, const std::string& check) const {
    return root / scenario / std::string(tier) / check;
  }
  // The tier holding `file` of this check: the family's, else "any", else nothing (a new golden).
  std::optional<std::string> find_tier(const std::string& scenario, const std::string& check, const std::string& file) const;
  std::filesystem::path bless_path(const std::string& scenario, const std::string& check, const std::string& file) const {
    return dir(scenario, family, check) / file;
  }
};

std::string frame_file(int frame, std::string_view extension = "png");

}  // namespace proxygi::regress
