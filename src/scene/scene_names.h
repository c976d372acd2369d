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
inline constexpr Name<ClipSegment::Mode> kSegmentMode[] = {
    {"loop", ClipSegment::Mode::loop},
    {"once", ClipSegment::Mode::once},
    {"ping_pong", ClipSegment::Mode::ping_pong}};
inline constexpr Name<Environment::Type> kEnvironmentType[] = {
    {"sky", Environment::Type::sky}, {"map", Environment::Type::map}};
inline constexpr Name<KeyframedCamera::Interpolation> kInterpolation[] = {
    {"linear", KeyframedCamera::Interpolation::linear},
    {"catmull_rom", KeyframedCamera::Interpolation::catmull_rom}};
// The render settings' names are defined with them (settings/render_settings.h).
inline constexpr const auto& kIndirectOperator = settings::kIndirectOperatorNames;
inline constexpr const auto& kExponential = settings::kExponentialNames;
inline constexpr const auto& kUpsampling = settings::kUpsamplingNames;
inline constexpr const auto& kSplatMethod = settings::kSplatMethodNames;
inline constexpr const auto& kShadingMethod = settings::kShadingMethodNames;
inline constexpr const auto& kTonemap = settings::kTonemapNames;
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
