// libFuzzer target for the scene-file parser (src/scene): any bytes either parse into a valid
// scene or fail with a message; a scene that parses writes back (to_json) to text that parses
// into the same scene (the writer's round-trip promise), so a mutation that breaks either aborts.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "scene/scene_parse.h"
#include "scene/scene_write.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto scene = proxygi::scene::parse_scene(text, "fuzz/scene.json");
  if (!scene) {
    if (scene.message().empty()) std::abort();  // every refusal says why
    return 0;
  }
  auto written = proxygi::scene::to_json(*scene);
  if (!written) std::abort();
  auto again = proxygi::scene::parse_scene(*written, "fuzz/scene.json");
  if (!again || !(*again == *scene)) std::abort();
  return 0;
}
