#pragma once
// The strings the scene file uses for each enum, shared by the reader and the writer so the two
// cannot drift apart. Order does not matter; every enumerator appears exactly once.
#include <string_view>
#include <utility>

#include "scene/scene.h"

namespace proxygi::scene::names {

template <class Enum>
using Name = std::pair<std::string_view, Enum>;

inline constexpr Name<WalkPath::Repeat> kRepeat[] = {
    {"none", WalkPath::Repeat::none},
    {"loop", WalkPath::Repeat::loop},
    {"ping_pong", WalkPath::Repeat::ping_pong}};
inline constexpr Name<Environment::Type> kEnvironmentType[] = {
    {"sky", Environment::Type::sky}, {"map", Environment::Type::map}};
inline constexpr Name<KeyframedCamera::Interpolation> kInterpolation[] = {
    {"linear", KeyframedCamera::Interpolation::linear},
    {"catmull_rom", KeyframedCamera::Interpolation::catmull_rom}};
inline constexpr Name<IndirectOperator> kIndirectOperator[] = {
    {"point", IndirectOperator::point},
    {"averaged", IndirectOperator::averaged},
    {"exact", IndirectOperator::exact}};
inline constexpr Name<Exponential> kExponential[] = {{"hyb", Exponential::hyb},
                                                     {"ol", Exponential::ol}};
inline constexpr Name<Upsampling> kUpsampling[] = {{"bilateral", Upsampling::bilateral},
                                                   {"bilinear", Upsampling::bilinear}};
inline constexpr Name<SplatMethod> kSplatMethod[] = {{"raster", SplatMethod::raster},
                                                     {"compute", SplatMethod::compute}};
inline constexpr Name<ShadingMethod> kShadingMethod[] = {{"image", ShadingMethod::image_space},
                                                         {"vertex", ShadingMethod::vertex},
                                                         {"ao", ShadingMethod::ambient_occlusion}};
inline constexpr Name<Tonemap> kTonemap[] = {
    {"aces", Tonemap::aces}, {"reinhard", Tonemap::reinhard}, {"clamp", Tonemap::clamp}};
inline constexpr Name<OutputFormat> kOutputFormat[] = {
    {"png", OutputFormat::png}, {"exr", OutputFormat::exr}, {"mp4", OutputFormat::mp4}};

// Camera "type" strings, in the order of the alternatives of Camera::kind.
inline constexpr std::string_view kCameraType[] = {"fixed", "orbit", "follow", "keyframed"};

template <class Enum, std::size_t N>
constexpr std::string_view name_of(const Name<Enum> (&table)[N], Enum value) {
  for (const auto& [name, e] : table) {
    if (e == value) return name;
  }
  return "?";
}

}  // namespace proxygi::scene::names
