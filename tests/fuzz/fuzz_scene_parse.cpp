// libFuzzer target for the scene parser (schema versions 1 and 2). A parsed scene must also
// write back and parse again to an equal scene (the writer and the reader agree).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "scene/scene_parse.h"
#include "scene/scene_write.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto scene = proxygi::scene::parse_scene(text, "fuzz/scene.json");
  if (!scene) return 0;
  auto written = proxygi::scene::to_json(*scene);
  if (!written) return 0;
  auto again = proxygi::scene::parse_scene(*written, "fuzz/scene.json");
  if (!again || !(again->characters == scene->characters)) std::abort();
  return 0;
}
