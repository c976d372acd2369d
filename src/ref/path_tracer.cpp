#include "ref/path_tracer.h"

#include <algorithm>

namespace proxygi::ref {

PathTracer::PathTracer(const EmbreeScene& scene, const EnvironmentLight& lighting, const EnvironmentLight& background,
                       const PathTracerSettings& settings)
    : scene_(scene), lighting_(lighting), background_(background), settings_(settings) {}

PathSample PathTracer::trace(const scene::Ray& ray, SampleStream& random) const {
  const std::optional<SurfaceHit> hit = scene_.intersect(ray.origin, ray.direction);
  if (!hit) {
    PathSample sample;
    sample.radiance = background_.radiance(ray.direction);
    sample.rays = 1;
    return sample;
  }
  PathSample sample = shade(*hit, random);
  sample.rays += 1;
  return sample;
}

PathSample PathTracer::shade(const SurfaceHit& first, SampleStream& random) const {
  int max_bounces = 0;
  switch (settings_.transport) {
    case LightTransport::direct: max_bounces = 0; break;
    case LightTransport::one_bounce: max_bounces = 1; break;
    case LightTransport::multi_bounce: max_bounces = std::max(settings_.max_bounces, 0); break;
  }

  PathSample out;
  out.hit = true;
  SurfaceHit vertex = first;
  glm::vec3 throughput(1.0f);
  for (int bounce = 0;; ++bounce) {
    const glm::vec3& n = vertex.shading_normal;
    if (bounce > 0 && vertex.character && !settings_.character_senders) vertex.albedo = glm::vec3(0.0f);
    const glm::vec3 f = vertex.albedo * (1.0f / kPi);
    const bool unshadowed = bounce > 0 && vertex.character && settings_.unshadowed_character_senders;
    glm::vec3 contribution(0.0f);

    // Sun: next-event estimation, MIS-weighted against the BSDF sample below.
    const glm::vec2 u_light = random.next_2d();
    if (lighting_.has_sun()) {
      const glm::vec3 d = sample_uniform_cone(lighting_.sun_direction(), lighting_.sun_cos_radius(), u_light);
      const float cos_theta = glm::dot(n, d);
      if (cos_theta > 0.0f && glm::dot(vertex.geometric_normal, d) > 0.0f) {
        ++out.rays;
        if (unshadowed || !scene_.occluded(offset_ray_origin(vertex, d), d)) {
          const float pdf_light = uniform_cone_pdf(lighting_.sun_cos_radius());
          const float weight = power_heuristic(pdf_light, cosine_hemisphere_pdf(cos_theta));
          contribution += f * lighting_.sun_radiance() * (cos_theta * weight / pdf_light);
        }
      }
    }

    // Environment (sh, map): next-event estimation from the tabulated sampler, MIS as the sun.
    const glm::vec2 u_environment = random.next_2d();
    const EquirectSampler* environment_sampler = lighting_.importance();
    if (environment_sampler) {
      float pdf_environment = 0.0f;
      const glm::vec3 d = environment_sampler->sample(u_environment, pdf_environment);
      const float cos_theta = glm::dot(n, d);
      if (pdf_environment > 0.0f && cos_theta > 0.0f && glm::dot(vertex.geometric_normal, d) > 0.0f) {
        ++out.rays;
        if (unshadowed || !scene_.occluded(offset_ray_origin(vertex, d), d)) {
          const float weight = power_heuristic(pdf_environment, cosine_hemisphere_pdf(cos_theta));
          contribution += f * lighting_.radiance_without_sun(d) * (cos_theta * weight / pdf_environment);
        }
      }
    }

    // BSDF sample: cosine-weighted, so f cos / pdf = albedo.
    const glm::vec3 d = sample_cosine_hemisphere(n, random.next_2d());
    const bool above_surface = glm::dot(vertex.geometric_normal, d) > 0.0f;
    std::optional<SurfaceHit> next;
    if (above_surface) {
      ++out.rays;
      next = scene_.intersect(offset_ray_origin(vertex, d), d);
      if (unshadowed) next.reset();  // the sky as if nothing blocked it (the path ends here anyway)
      if (!next) {
        glm::vec3 environment = lighting_.radiance_without_sun(d);
        if (environment_sampler)
          environment *= power_heuristic(cosine_hemisphere_pdf(glm::dot(n, d)), environment_sampler->pdf(d));
        if (lighting_.in_sun(d)) {
          const float weight = power_heuristic(cosine_hemisphere_pdf(glm::dot(n, d)),
                                               uniform_cone_pdf(lighting_.sun_cos_radius()));
          environment += weight * lighting_.sun_radiance();
        }
        contribution += vertex.albedo * environment;
      }
    }

    const glm::vec3 weighted = throughput * contribution;
    out.radiance += weighted;
    if (bounce > 0) out.indirect += weighted;

    if (!next || bounce + 1 > max_bounces) break;
    throughput *= vertex.albedo;
    if (bounce + 1 >= settings_.russian_roulette_depth && settings_.transport == LightTransport::multi_bounce) {
      const float survive = std::min(1.0f, std::max({throughput.r, throughput.g, throughput.b}));
      if (random.next_float() >= survive) break;
      throughput /= survive;
    }
    vertex = *next;
  }
  return out;
}

}  // namespace proxygi::ref
