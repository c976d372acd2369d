// libFuzzer target for the proxy rig parser (proxies/rig_file.h) against the procedural
// mannequin: any bytes either give a rig or fail with a message; a rig that parses is
// compiled for tracking (bones, weights and radii it names must be usable).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "anim/mannequin.h"
#include "proxies/rig_file.h"
#include "proxies/tracking.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const proxygi::anim::Character character = proxygi::anim::build_mannequin();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto rig = proxygi::proxies::parse_rig(text, "fuzz.proxies.json", character);
  if (!rig) {
    if (rig.message().empty()) std::abort();
    return 0;
  }
  auto tracking = proxygi::proxies::compile_tracking(*rig, character, rig->binding);
  if (!tracking && tracking.message().empty()) std::abort();
  return 0;
}
