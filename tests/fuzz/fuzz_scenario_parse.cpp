// libFuzzer target for regression scenario files (regress/scenario.h): any input gives a
// scenario or an error naming a field, never a crash. Scene paths resolve under fuzz/ (absent).
#include <cstdint>
#include <string_view>

#include "regress/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto scenario = proxygi::regress::parse_scenario(text, "fuzz/scenario.json", "fuzz");
  if (scenario && scenario->checks.empty()) __builtin_trap();  // the parser requires checks
  return 0;
}
