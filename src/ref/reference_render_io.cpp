#include "ref/reference_render_io.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "ref/guided_filter.h"
#include "settings/limits.h"

namespace proxygi::ref {
namespace {

std::filesystem::path sibling(const std::filesystem::path& output, const std::string& suffix) {
  std::filesystem::path out = output;
  out.replace_extension();
  out += suffix;
  return out;
}

nlohmann::json to_json(const ReferenceRecord& r) {
  return {{"scene", r.scene},       {"frame", r.frame},         {"time_s", r.time_s},
          {"width", r.width},       {"height", r.height},       {"transport", r.transport},
          {"lighting", r.lighting}, {"sh_order", r.sh_order},   {"seed", r.seed},
          {"sampler", r.sampler},   {"samples", r.samples},   {"target_samples", std::max(r.target_samples, r.samples)},
          {"guided_filter", r.guided_filter}, {"seconds", r.seconds}, {"rays", r.rays}};
}

constexpr std::string_view kPartialMagic = "proxygi-sums 1\n";
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "OUT.partial stores dvec3 as three doubles");

}  // namespace

ReferencePaths reference_paths(const std::filesystem::path& output) {
  ReferencePaths p;
  p.radiance = sibling(output, ".exr");
  p.unfiltered = sibling(output, ".unfiltered.exr");
  p.indirect = sibling(output, ".indirect.exr");
  p.variance = sibling(output, ".variance.exr");
  p.albedo = sibling(output, ".albedo.exr");
  p.normal = sibling(output, ".normal.exr");
  p.depth = sibling(output, ".depth.exr");
  p.mask = sibling(output, ".mask.exr");
  p.character = sibling(output, ".character.exr");
  p.record = sibling(output, ".json");
  p.partial = sibling(output, ".partial");
  return p;
}

Result<ReferenceRecord> read_record(const std::filesystem::path& path) {
  auto bytes = read_file(path, 1u << 20);
  if (!bytes) return bytes.error();
  try {
    const nlohmann::json j = nlohmann::json::parse(bytes->begin(), bytes->end());
    ReferenceRecord r;
    r.scene = j.at("scene").get<std::string>();
    r.frame = j.at("frame").get<int>();
    r.time_s = j.at("time_s").get<double>();
    r.width = j.at("width").get<int>();
    r.height = j.at("height").get<int>();
    r.transport = j.at("transport").get<std::string>();
    r.lighting = j.at("lighting").get<std::string>();
    r.sh_order = j.at("sh_order").get<int>();
    r.seed = j.at("seed").get<std::uint32_t>();
    r.sampler = j.value("sampler", std::string("random"));
    r.samples = j.at("samples").get<std::uint32_t>();
    r.target_samples = j.value("target_samples", r.samples);
    r.guided_filter = j.at("guided_filter").get<bool>();
    r.seconds = j.at("seconds").get<double>();
    r.rays = j.at("rays").get<std::uint64_t>();
    return r;
  } catch (const nlohmann::json::exception& e) {
    return make_error(path.string() + ": " + e.what());
  }
}

std::string record_mismatch(const ReferenceRecord& previous, const ReferenceRecord& current) {
  auto differs = [](const std::string& name, const auto& a, const auto& b) -> std::string {
    if (a == b) return {};
    nlohmann::json ja = a, jb = b;
    return name + " was " + ja.dump() + ", now " + jb.dump();
  };
  for (const std::string& difference :
       {differs("scene", previous.scene, current.scene), differs("frame", previous.frame, current.frame),
        differs("width", previous.width, current.width), differs("height", previous.height, current.height),
        differs("mode", previous.transport, current.transport), differs("lighting", previous.lighting, current.lighting),
        differs("sh_order", previous.sh_order, current.sh_order), differs("seed", previous.seed, current.seed),
        differs("sampler", previous.sampler, current.sampler)})
    if (!difference.empty()) return difference;
  return {};
}

Status write_partial_sums(const std::filesystem::path& path, const SampleSums& sums) {
  std::vector<std::uint8_t> bytes(kPartialMagic.begin(), kPartialMagic.end());
  auto put = [&bytes](const void* data, std::size_t size) {
    const auto* begin = static_cast<const std::uint8_t*>(data);
    bytes.insert(bytes.end(), begin, begin + size);
  };
  const std::uint32_t header[3] = {std::uint32_t(sums.width), std::uint32_t(sums.height), sums.samples};
  put(header, sizeof header);
  for (std::size_t i = 0; i < sums.radiance.size(); ++i) {
    put(&sums.radiance[i], sizeof(glm::dvec3));
    put(&sums.radiance_squared[i], sizeof(glm::dvec3));
    put(&sums.indirect[i], sizeof(glm::dvec3));
  }
  return write_file_atomically(path, bytes);
}

Result<SampleSums> read_partial_sums(const std::filesystem::path& path) {
  constexpr std::uint64_t kMaxPixels = std::uint64_t(settings::kMaxImageSize) * settings::kMaxImageSize;
  auto bytes = read_file(path, kPartialMagic.size() + 12 + kMaxPixels * 9 * sizeof(double));
  if (!bytes) return bytes.error();
  const std::size_t header = kPartialMagic.size() + 12;
  if (bytes->size() < header || std::string_view(reinterpret_cast<const char*>(bytes->data()), kPartialMagic.size()) != kPartialMagic)
    return make_error(path.string() + ": not a proxygi sample-sums file");
  std::uint32_t fields[3];
  std::memcpy(fields, bytes->data() + kPartialMagic.size(), sizeof fields);
  SampleSums sums;
  sums.width = int(fields[0]);
  sums.height = int(fields[1]);
  sums.samples = fields[2];
  const std::uint64_t pixels = std::uint64_t(fields[0]) * fields[1];
  if (fields[0] > std::uint32_t(settings::kMaxImageSize) || fields[1] > std::uint32_t(settings::kMaxImageSize) ||
      bytes->size() != header + pixels * 9 * sizeof(double))
    return make_error(path.string() + ": truncated or of another size (" + std::to_string(fields[0]) + "x" +
                      std::to_string(fields[1]) + ")");
  sums.radiance.resize(pixels);
  sums.radiance_squared.resize(pixels);
  sums.indirect.resize(pixels);
  const std::uint8_t* at = bytes->data() + header;
  for (std::size_t i = 0; i < pixels; ++i) {
    std::memcpy(&sums.radiance[i], at, sizeof(glm::dvec3)), at += sizeof(glm::dvec3);
    std::memcpy(&sums.radiance_squared[i], at, sizeof(glm::dvec3)), at += sizeof(glm::dvec3);
    std::memcpy(&sums.indirect[i], at, sizeof(glm::dvec3)), at += sizeof(glm::dvec3);
  }
  return sums;
}

Result<SampleSums> read_previous_sums(const ReferencePaths& paths, const ReferenceRecord& record) {
  std::error_code missing;
  if (std::filesystem::exists(paths.partial, missing)) {
    auto exact = read_partial_sums(paths.partial);
    if (!exact) return exact.error();
    if (exact->samples == record.samples && exact->width == record.width && exact->height == record.height) return exact;
  }
  ReferenceImages images;
  const std::filesystem::path& mean_path = record.guided_filter ? paths.unfiltered : paths.radiance;
  auto radiance = image::read_image(mean_path);
  if (!radiance) return radiance.error();
  auto indirect = image::read_image(paths.indirect);
  if (!indirect) return indirect.error();
  auto variance = image::read_image(paths.variance);
  if (!variance) return variance.error();
  images.radiance = std::move(*radiance);
  images.indirect = std::move(*indirect);
  images.variance = std::move(*variance);
  if (images.radiance.width != record.width || images.radiance.height != record.height)
    return make_error(mean_path.string() + ": size differs from its record");
  return from_images(images, record.samples);
}

Result<image::ImageF> guided_filter_reference(const ReferenceImages& images, const PixelFeatures& features,
                                              const GuidedFilterSettings& settings) {
  GuideFeatures guide;
  guide.normal = &features.normal;
  guide.depth = &features.depth;
  guide.depth_scale = settings.depth_scale;
  GuidedFilterOptions options;
  options.radius = settings.radius;
  auto filtered = guided_filter_indirect(images.indirect, guide, options);
  if (!filtered) return filtered.error();
  image::ImageF out = images.radiance;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    if (features.mask.pixels[i].r == 0.0f) continue;  // background: environment radiance as traced
    const glm::vec3 direct = glm::vec3(images.radiance.pixels[i]) - glm::vec3(images.indirect.pixels[i]);
    // The filter's linear model can undershoot near edges: radiance is never negative.
    const glm::vec3 indirect = glm::max(glm::vec3(filtered->pixels[i]), glm::vec3(0.0f));
    out.pixels[i] = glm::vec4(direct + indirect, 1.0f);
  }
  return out;
}

Status write_reference(const ReferencePaths& paths, const ReferenceImages& images, const PixelFeatures& features,
                       const ReferenceRecord& record, const image::ImageF* filtered) {
  const std::vector<std::pair<const std::filesystem::path*, const image::ImageF*>> files = {
      {&paths.radiance, filtered ? filtered : &images.radiance},
      {&paths.indirect, &images.indirect},
      {&paths.variance, &images.variance},
      {&paths.albedo, &features.albedo},
      {&paths.normal, &features.normal},
      {&paths.depth, &features.depth},
      {&paths.mask, &features.mask},
      {&paths.character, &features.character}};
  for (const auto& [path, image] : files)
    if (image->width > 0)  // features made by hand may leave the character mask out
      if (Status s = image::write_exr(*path, *image); !s) return s;
  if (filtered)
    if (Status s = image::write_exr(paths.unfiltered, images.radiance); !s) return s;
  // The record goes last: a run interrupted before it leaves the previous record in place.
  return write_file_atomically(paths.record, to_json(record).dump(2) + "\n");
}

}  // namespace proxygi::ref
