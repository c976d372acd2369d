#pragma once
// Base64 data URIs, so report.html carries its images inside (self-contained).
#include <cstdint>
#include <span>
#include <string>

namespace proxygi::regress {

std::string base64(std::span<const std::uint8_t> bytes);
std::string png_data_uri(std::span<const std::uint8_t> png_bytes);

}  // namespace proxygi::regress
