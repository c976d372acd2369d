#pragma once
// `proxygi compare`'s region and bounds scores (the stability study's metrics, study/stability_metrics.h):
//   --unshadowed IMAGE  the same frame without proxies: bounds (a channel above it by more than
//                       1/255 of it) and the shadow region (reference luminance < 99 % of it)
//   --depth IMAGE       eye depth in the red channel (0 = background), as `proxygi reference`'s
//                       features write it: the edge band (--edge-radius pixels around depth jumps
//                       of more than 10 %) and the interior (receivers outside the band)
//   --character IMAGE   the reference's character region (`proxygi reference`'s .character.exr,
//                       white = character): the body as receiver
// Negative and NaN/Inf pixels (any channel) are counted always. Regions are intersected with the
// receiver mask; an empty region reports null scores.
#include <string>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics.h"

namespace proxygi::app {

struct RegionInputs {
  std::string unshadowed;  // path or empty
  std::string depth;       // path or empty
  std::string character;   // path or empty
  int edge_radius = 1;
};

// {"bounds": {...}, "regions": {"shadow"|"edge_band"|"interior"|"character": {"pixels", "rmse", "relative_mse"}}}.
// Fails (bad input) when an image cannot be read or differs in size from the test image.
Result<nlohmann::json> region_scores(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask* receivers,
                                     const RegionInputs& inputs);
std::string region_text(const nlohmann::json& scores);

}  // namespace proxygi::app
