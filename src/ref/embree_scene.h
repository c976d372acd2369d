#pragma once
// The reference path tracer's geometry: world-space triangle meshes and analytic spheres with
// Lambertian materials, in one Embree 3 scene (built once per frame with MEDIUM quality and the
// ROBUST flag so rays do not leak through shared edges; see notes/rendering-notes.md §1.2).
//
// Conventions: world space (glTF: right-handed, +Y up, meters). Every surface is double-sided:
// hits report normals turned toward the incoming ray. Albedo is linear RGB in [0, 1]:
// material albedo × texture texel (render/texture_sampling.h: level 0 of the glTF sampler's
// wrap and magnification filter at the KHR_texture_transform'ed uv, texels already decoded
// sRGB → linear). No mip levels: the pixel's many path samples average the texture over its
// footprint, which the GPU's trilinear mipmapping approximates.
// The scene is immutable after build() and safe to query from many threads at once.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "base/result.h"

// Embree's opaque handles, declared here so users need not include <embree3/rtcore.h>.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace proxygi::ref {

// Linear RGB texture, row-major, top row first (glTF: uv (0, 0) is the top-left corner).
struct LinearTexture {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> texels;
  // Level-0 lookup at texture coordinate uv with the sampler's wrap and magnification filter.
  glm::vec3 sample(const glm::vec2& uv, const anim::TextureSampler& sampler = {}) const;
};

struct SurfaceMaterial {
  glm::vec3 albedo{0.8f};                        // linear RGB (glTF base color factor)
  std::shared_ptr<const LinearTexture> texture;  // multiplies albedo at the hit's uv; may be null
  anim::TextureSampler sampler;                  // the texture's glTF sampler
  glm::mat3 uv_transform{1.0f};                  // KHR_texture_transform (anim::Material)
};

// A world-space triangle mesh. normals and uvs are per vertex or empty.
struct TriangleMesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;  // 3 per triangle
  SurfaceMaterial material;
  bool character = false;  // part of a character (its pixels form the "character" region)
};

// An exact sphere (Embree sphere points): used for analytic tests and for tracing proxy spheres.
struct SphereShape {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  SurfaceMaterial material;
  bool character = false;  // as TriangleMesh::character (analytic senders in bounce tests)
};

struct SurfaceHit {
  float distance = 0.0f;              // along the (unit) ray direction, meters
  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f};   // unit, facing the ray origin
  glm::vec3 shading_normal{0.0f};     // unit, interpolated vertex normal on the geometric side
  glm::vec3 albedo{0.0f};
  bool character = false;             // the mesh hit is a character's
  // Which surface point: mesh index into build()'s meshes and triangle (kNoTriangle for a sphere),
  // barycentrics (u, v) of indices 1 and 2. The same point of a re-posed copy of the meshes is
  // (1 − u − v) p0 + u p1 + v p2 of that triangle (exact reprojection).
  static constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;
  std::uint32_t mesh = kNoTriangle, triangle = kNoTriangle;
  glm::vec2 barycentric{0.0f};
};

class EmbreeScene {
 public:
  // Copies the meshes (normals and uvs are needed at hit time). Fails on indices out of range,
  // non-finite positions, mismatched normal/uv counts, or an Embree error.
  static Result<EmbreeScene> build(std::vector<TriangleMesh> meshes, std::span<const SphereShape> spheres = {});

  EmbreeScene(EmbreeScene&& other) noexcept;
  EmbreeScene& operator=(EmbreeScene&& other) noexcept;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene();

  // Closest hit along origin + t * direction, t in (0, max_distance]; direction must be unit.
  std::optional<SurfaceHit> intersect(const glm::vec3& origin, const glm::vec3& direction,
                                      float max_distance = INFINITY) const;
  // True when anything lies along the ray within (0, max_distance).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance = INFINITY) const;

  std::size_t triangle_count() const { return triangle_count_; }

 private:
  EmbreeScene() = default;
  void release();

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<TriangleMesh> meshes_;       // geometry id i < meshes_.size(): mesh i
  std::vector<SphereShape> spheres_;       // geometry id meshes_.size(): all spheres, prim id = index
  std::size_t triangle_count_ = 0;
};

// A ray origin nudged off a surface along its geometric normal, toward `direction`'s side, so
// the next ray does not re-hit the surface it leaves (scaled to the position's magnitude).
glm::vec3 offset_ray_origin(const SurfaceHit& hit, const glm::vec3& direction);

}  // namespace proxygi::ref
