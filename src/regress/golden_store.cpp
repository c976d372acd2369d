#include "regress/golden_store.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace proxygi::regress {

std::string device_family(std::string_view device_name) {
  std::string lower(device_name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const std::pair<std::string_view, std::string_view> families[] = {
      {"llvmpipe", "llvmpipe"}, {"lavapipe", "llvmpipe"}, {"swiftshader", "swiftshader"}, {"nvidia", "nvidia"},
      {"geforce", "nvidia"},    {"quadro", "nvidia"},     {"tesla", "nvidia"},            {"amd", "amd"},
      {"radeon", "amd"},        {"radv", "amd"},          {"intel", "intel"},             {"apple", "apple"}};
  for (const auto& [needle, family] : families)
    if (lower.find(needle) != std::string::npos) return std::string(family);
  return "other";
}

std::optional<std::string> GoldenStore::find_tier(const std::string& scenario, const std::string& check,
                                                  const std::string& file) const {
  std::error_code error;
  for (const std::string& tier : {family, std::string(kFallbackTier)})
    if (std::filesystem::exists(dir(scenario, tier, check) / file, error)) return tier;
  return std::nullopt;
}

std::string frame_file(int frame, std::string_view extension) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%05d.", frame);
  return std::string(name) + std::string(extension);
}

}  // namespace proxygi::regress
