#include "ref/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include <embree3/rtcore.h>

#include "render/texture_sampling.h"

namespace proxygi::ref {
namespace {

std::string device_error_text(RTCDevice device) {
  switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

Status validate_mesh(const TriangleMesh& mesh, std::size_t index) {
  const std::string where = "mesh " + std::to_string(index) + " (" + mesh.name + ")";
  if (mesh.indices.size() % 3 != 0) return make_error(where + ": index count is not a multiple of 3");
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    return make_error(where + ": normal count differs from position count");
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
    return make_error(where + ": uv count differs from position count");
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      return make_error(where + ": index " + std::to_string(i) + " out of range (" +
                        std::to_string(mesh.positions.size()) + " vertices)");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i].x) || !std::isfinite(mesh.positions[i].y) || !std::isfinite(mesh.positions[i].z))
      return make_error(where + ": position " + std::to_string(i) + " is not finite");
  return {};
}

glm::vec3 material_albedo(const SurfaceMaterial& material, const glm::vec2& uv) {
  if (!material.texture) return material.albedo;
  return material.albedo * material.texture->sample(render::transform_uv(material.uv_transform, uv), material.sampler);
}

}  // namespace

glm::vec3 LinearTexture::sample(const glm::vec2& uv, const anim::TextureSampler& sampler) const {
  return render::sample_texels(texels, width, height, uv, sampler.wrap_s, sampler.wrap_t, sampler.magnification);
}

Result<EmbreeScene> EmbreeScene::build(std::vector<TriangleMesh> meshes, std::span<const SphereShape> spheres) {
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (Status s = validate_mesh(meshes[i], i); !s) return s.error();
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (!(spheres[i].radius > 0.0f) || !std::isfinite(spheres[i].radius))
      return make_error("sphere " + std::to_string(i) + ": radius must be positive and finite");

  EmbreeScene out;
  out.device_ = rtcNewDevice(nullptr);
  if (!out.device_) return make_error("embree: cannot create a device (" + device_error_text(nullptr) + ")");
  out.scene_ = rtcNewScene(out.device_);
  rtcSetSceneFlags(out.scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(out.scene_, RTC_BUILD_QUALITY_MEDIUM);

  out.meshes_ = std::move(meshes);
  for (std::size_t i = 0; i < out.meshes_.size(); ++i) {
    const TriangleMesh& mesh = out.meshes_[i];
    RTCGeometry geometry = rtcNewGeometry(out.device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.indices.size() / 3));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geometry);
      return make_error("embree: mesh " + std::to_string(i) + ": " + device_error_text(out.device_));
    }
    if (!mesh.positions.empty()) std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    if (!mesh.indices.empty()) std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    // Geometry ids are assigned in attach order from 0, so id i is mesh i.
    rtcAttachGeometry(out.scene_, geometry);
    rtcReleaseGeometry(geometry);
    out.triangle_count_ += mesh.indices.size() / 3;
  }
  out.spheres_.assign(spheres.begin(), spheres.end());
  if (!out.spheres_.empty()) {
    RTCGeometry geometry = rtcNewGeometry(out.device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                               4 * sizeof(float), out.spheres_.size()));
    if (!points) {
      rtcReleaseGeometry(geometry);
      return make_error("embree: spheres: " + device_error_text(out.device_));
    }
    for (std::size_t i = 0; i < out.spheres_.size(); ++i) {
      const SphereShape& s = out.spheres_[i];
      points[4 * i + 0] = s.center.x;
      points[4 * i + 1] = s.center.y;
      points[4 * i + 2] = s.center.z;
      points[4 * i + 3] = s.radius;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(out.scene_, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(out.scene_);
  if (rtcGetDeviceError(out.device_) != RTC_ERROR_NONE)
    return make_error("embree: scene build failed: " + device_error_text(out.device_));
  return out;
}

EmbreeScene::EmbreeScene(EmbreeScene&& other) noexcept { *this = std::move(other); }

EmbreeScene& EmbreeScene::operator=(EmbreeScene&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, nullptr);
    scene_ = std::exchange(other.scene_, nullptr);
    meshes_ = std::move(other.meshes_);
    spheres_ = std::move(other.spheres_);
    triangle_count_ = std::exchange(other.triangle_count_, 0);
  }
  return *this;
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::release() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
  scene_ = nullptr;
  device_ = nullptr;
}

std::optional<SurfaceHit> EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& direction,
                                                 float max_distance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = origin.x;
  query.ray.org_y = origin.y;
  query.ray.org_z = origin.z;
  query.ray.dir_x = direction.x;
  query.ray.dir_y = direction.y;
  query.ray.dir_z = direction.z;
  query.ray.tnear = 0.0f;
  query.ray.tfar = max_distance;
  query.ray.mask = 0xFFFFFFFFu;
  query.ray.flags = 0;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  SurfaceHit hit;
  hit.distance = query.ray.tfar;
  hit.position = origin + direction * hit.distance;
  glm::vec3 geometric(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  glm::vec3 shading(0.0f);
  if (query.hit.geomID < meshes_.size()) {
    const TriangleMesh& mesh = meshes_[query.hit.geomID];
    const std::uint32_t* tri = &mesh.indices[3 * std::size_t(query.hit.primID)];
    const float u = query.hit.u, v = query.hit.v, w = 1.0f - u - v;
    // Barycentric position is more accurate than origin + t d for long rays.
    hit.position = w * mesh.positions[tri[0]] + u * mesh.positions[tri[1]] + v * mesh.positions[tri[2]];
    if (!mesh.normals.empty()) shading = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
    const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0f) : w * mesh.uvs[tri[0]] + u * mesh.uvs[tri[1]] + v * mesh.uvs[tri[2]];
    hit.albedo = material_albedo(mesh.material, uv);
    hit.character = mesh.character;
    hit.mesh = query.hit.geomID;
    hit.triangle = query.hit.primID;
    hit.barycentric = glm::vec2(u, v);
  } else {
    const SphereShape& sphere = spheres_[query.hit.primID];
    geometric = hit.position - sphere.center;
    hit.albedo = sphere.material.albedo;  // spheres carry no uvs
    hit.character = sphere.character;
  }
  const float geometric_length = glm::length(geometric);
  if (!(geometric_length > 0.0f)) geometric = -direction;
  else geometric /= geometric_length;
  if (glm::dot(geometric, direction) > 0.0f) geometric = -geometric;
  const float shading_length = glm::length(shading);
  shading = shading_length > 1e-12f ? shading / shading_length : geometric;
  if (glm::dot(shading, geometric) < 0.0f) shading = -shading;
  hit.geometric_normal = geometric;
  hit.shading_normal = shading;
  return hit;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tnear = 0.0f;
  ray.tfar = max_distance;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction) {
  const float magnitude = std::max({1.0f, std::abs(hit.position.x), std::abs(hit.position.y), std::abs(hit.position.z)});
  const float epsilon = 1e-4f * magnitude;
  const glm::vec3 side = glm::dot(direction, hit.geometric_normal) >= 0.0f ? hit.geometric_normal : -hit.geometric_normal;
  return hit.position + side * epsilon;
}

}  // namespace proxygi::ref
