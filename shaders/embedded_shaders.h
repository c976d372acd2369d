#pragma once
// SPIR-V of every shader in shaders/, compiled at build time and linked into the binary.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace proxygi::shaders {

// Returns the SPIR-V words of a shader by its file name ("test_pattern.comp"); empty if unknown.
std::span<const std::uint32_t> spirv(std::string_view file_name);

// Every embedded shader's file name, for listings and tests.
std::vector<std::string_view> names();

}  // namespace proxygi::shaders
