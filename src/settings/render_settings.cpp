#include "settings/render_settings.h"

#include <algorithm>
#include <cmath>

namespace proxygi::settings {

bool is_receiver_scale(int k) { return std::find(kReceiverScales.begin(), kReceiverScales.end(), k) != kReceiverScales.end(); }

float exposure_multiplier(const RenderSettings& settings) { return std::exp2(settings.exposure_ev); }

int supersampling_factor(Antialiasing antialiasing) {
  switch (antialiasing) {
    case Antialiasing::ssaa2: return 2;
    case Antialiasing::ssaa4: return 4;
    case Antialiasing::off: break;
  }
  return 1;
}

std::string_view name_of(ShadingMethod value) { return name_of(kShadingMethodNames, value); }
std::string_view name_of(IndirectOperator value) { return name_of(kIndirectOperatorNames, value); }
std::string_view name_of(IndirectMethod value) { return name_of(kIndirectMethodNames, value); }
std::string_view name_of(VsglGrouping value) { return name_of(kVsglGroupingNames, value); }
std::string_view name_of(VsglSun value) { return name_of(kVsglSunNames, value); }
std::string_view name_of(ProxyLod value) { return name_of(kProxyLodNames, value); }
std::string_view name_of(Exponential value) { return name_of(kExponentialNames, value); }
std::string_view name_of(Upsampling value) { return name_of(kUpsamplingNames, value); }
std::string_view name_of(SplatMethod value) { return name_of(kSplatMethodNames, value); }
std::string_view name_of(Tonemap value) { return name_of(kTonemapNames, value); }
std::string_view name_of(StaticTransfer value) { return name_of(kStaticTransferNames, value); }
std::string_view name_of(Antialiasing value) { return name_of(kAntialiasingNames, value); }

}  // namespace proxygi::settings
