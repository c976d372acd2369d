#include "study/bounce_scores.h"

#include <string>

namespace proxygi::study {
namespace {

Status same_size(const image::ImageF& a, const image::ImageF& b) {
  if (a.width == b.width && a.height == b.height) return {};
  return make_error("bounce: size mismatch: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " against " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
}

void accumulate(BounceError& sum, int& count, const BounceError& frame) {
  if (frame.relative_mse < 0.0) return;
  if (count == 0) sum = {0.0, 0.0, 0};
  sum.relative_mse += frame.relative_mse;
  sum.luminance_ratio += frame.luminance_ratio;
  sum.pixels += frame.pixels;
  ++count;
}

void finish(BounceError& sum, int count) {
  if (count == 0) return;
  sum.relative_mse /= count;
  sum.luminance_ratio /= count;
  sum.pixels /= std::size_t(count);
}

}  // namespace

Result<image::ImageF> bounce_image(const image::ImageF& with, const image::ImageF& without) {
  if (Status s = same_size(with, without); !s) return s.error();
  image::ImageF out(with.width, with.height);
  for (std::size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = glm::vec4(glm::vec3(with.pixels[i]) - glm::vec3(without.pixels[i]), 1.0f);
  return out;
}

ref::ReceiverMask significant_bounce(const image::ImageF& bounce, const image::ImageF& full,
                                     const ref::ReceiverMask& receivers, double fraction) {
  ref::ReceiverMask out = receivers;
  for (std::size_t i = 0; i < out.receiver.size(); ++i) {
    const double b = image::rec709_luminance(bounce.pixels[i]);
    out.receiver[i] = receivers.receiver[i] != 0 && b > 0.0 && b >= fraction * image::rec709_luminance(full.pixels[i]);
  }
  return out;
}

Result<BounceReference> make_bounce_reference(const FrameReference& full, const FrameReference& without_senders) {
  auto bounce = bounce_image(full.radiance, without_senders.radiance);
  if (!bounce) return bounce.error();
  if (full.samples != without_senders.samples)
    return make_error("bounce: the references hold " + std::to_string(full.samples) + " and " +
                      std::to_string(without_senders.samples) + " samples (their noise would not cancel)");
  BounceReference out;
  out.bounce = std::move(*bounce);
  out.significant = significant_bounce(out.bounce, full.radiance, full.receivers);
  out.character = full.character;
  out.contact = full.contact;
  out.ground = full.ground;
  out.other = full.other;
  return out;
}

Result<BounceError> bounce_error(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask& mask) {
  if (Status s = same_size(test, reference); !s) return s.error();
  if (mask.width != reference.width || mask.height != reference.height)
    return make_error("bounce: the mask's size differs from the images'");
  double squared_error = 0.0, squared_reference = 0.0, test_luminance = 0.0, reference_luminance = 0.0;
  BounceError out;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    if (!mask.contains(i)) continue;
    const glm::dvec3 x(test.pixels[i]), r(reference.pixels[i]);
    squared_error += glm::dot(x - r, x - r);
    squared_reference += glm::dot(r, r);
    test_luminance += image::rec709_luminance(test.pixels[i]);
    reference_luminance += image::rec709_luminance(reference.pixels[i]);
    ++out.pixels;
  }
  if (out.pixels == 0 || squared_reference <= 0.0) return BounceError{};
  out.relative_mse = squared_error / squared_reference;
  out.luminance_ratio = reference_luminance > 0.0 ? test_luminance / reference_luminance : -1.0;
  return out;
}

Result<BounceScores> score_bounce(const image::ImageF& test_bounce, const BounceReference& reference) {
  BounceScores out;
  const std::pair<BounceError*, const ref::ReceiverMask*> parts[] = {{&out.significant, &reference.significant},
                                                                     {&out.character, &reference.character},
                                                                     {&out.contact, &reference.contact},
                                                                     {&out.ground, &reference.ground},
                                                                     {&out.other, &reference.other}};
  for (const auto& [error, mask] : parts) {
    auto scored = bounce_error(test_bounce, reference.bounce, *mask);
    if (!scored) return scored.error();
    *error = *scored;
  }
  return out;
}

BounceScores mean_bounce_scores(const std::vector<BounceScores>& frames) {
  BounceScores mean;
  int counts[5] = {0, 0, 0, 0, 0};
  for (const BounceScores& frame : frames) {
    accumulate(mean.significant, counts[0], frame.significant);
    accumulate(mean.character, counts[1], frame.character);
    accumulate(mean.contact, counts[2], frame.contact);
    accumulate(mean.ground, counts[3], frame.ground);
    accumulate(mean.other, counts[4], frame.other);
  }
  finish(mean.significant, counts[0]);
  finish(mean.character, counts[1]);
  finish(mean.contact, counts[2]);
  finish(mean.ground, counts[3]);
  finish(mean.other, counts[4]);
  return mean;
}

}  // namespace proxygi::study
