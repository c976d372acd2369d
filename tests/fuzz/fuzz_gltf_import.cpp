// libFuzzer target for the glTF importer. Each input is imported twice: as given (GLB when it
// starts with the GLB magic, else glTF JSON), and wrapped as the JSON chunk of a GLB whose BIN
// chunk holds a fixed byte pattern, so JSON mutations also reach the GLB path. External URIs
// resolve inside a scratch folder holding one small file, "a.bin".
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "anim/gltf_import.h"

namespace {

std::filesystem::path g_folder;

proxygi::anim::ImportLimits fuzz_limits() {
  proxygi::anim::ImportLimits limits;
  limits.max_file_bytes = 1u << 20;
  limits.max_accessor_elements = 1u << 16;
  limits.max_total_elements = 1u << 20;
  limits.max_objects = 1024;
  limits.max_image_dimension = 512;
  limits.max_image_pixels = 1u << 16;
  limits.max_total_image_pixels = 1u << 18;
  return limits;
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

std::vector<std::uint8_t> wrap_as_glb(const std::uint8_t* json, std::size_t size) {
  std::vector<std::uint8_t> chunk(json, json + size);
  while (chunk.size() % 4 != 0) chunk.push_back(' ');
  std::vector<std::uint8_t> bin(256);
  for (std::size_t i = 0; i < bin.size(); ++i) bin[i] = static_cast<std::uint8_t>(i * 37u);
  std::vector<std::uint8_t> out;
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(12 + 8 + chunk.size() + 8 + bin.size()));
  append_u32(out, static_cast<std::uint32_t>(chunk.size()));
  append_u32(out, 0x4E4F534Au);  // JSON
  out.insert(out.end(), chunk.begin(), chunk.end());
  append_u32(out, static_cast<std::uint32_t>(bin.size()));
  append_u32(out, 0x004E4942u);  // BIN
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_folder = std::filesystem::temp_directory_path() / ("proxygi-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(g_folder);
  std::ofstream bin(g_folder / "a.bin", std::ios::binary);
  for (int i = 0; i < 64; ++i) bin.put(static_cast<char>(i));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;
  const auto limits = fuzz_limits();
  const std::span<const std::uint8_t> bytes(data, size);
  (void)proxygi::anim::import_gltf_bytes(bytes, "fuzz", g_folder, limits);
  if (size >= 4 && std::memcmp(data, "glTF", 4) != 0) {
    const auto glb = wrap_as_glb(data, size);
    (void)proxygi::anim::import_gltf_bytes(glb, "fuzz.glb", g_folder, limits);
  }
  return 0;
}
