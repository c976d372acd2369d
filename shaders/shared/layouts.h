// Constants and struct layouts shared by C++ and GLSL. Included from GLSL with
// GL_GOOGLE_include_directive and from C++ (where the sizes are static_asserted against std430).
// Only scalar, vec4-aligned members: a struct here has the same bytes on both sides.
#ifndef PROXYGI_SHADERS_SHARED_LAYOUTS_H
#define PROXYGI_SHADERS_SHARED_LAYOUTS_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace proxygi::gpu_layout {
using uint = std::uint32_t;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
#define PROXYGI_CONST(type, name, value) inline constexpr type name = value
#else
#define PROXYGI_CONST(type, name, value) const type name = value
#endif

// ---- test passes (foundation) ----
PROXYGI_CONST(uint, kTestPatternLocalSize, 64u);

// Push constants of test_pattern.comp: element i of the output gets i * multiplier + offset.
struct TestPatternPush {
  uint element_count;
  uint multiplier;
  uint offset;
  uint padding;
};

// ---- skin.comp: linear blend skinning (mirrors anim/skinning.h SkinningJob) ----
PROXYGI_CONST(uint, kSkinLocalSize, 64u);

// Inputs per vertex: bind positions and normals as packed float triples, palette indices as
// uint16 packed two per uint (low half first), weights as floats, `influences` of each per
// vertex. Outputs: world-space vec4 positions (w = 1) and normals (w = 0).
// Morph targets (anim::MorphJob) first: deltas as packed float triples, target-major
// (target t, vertex v at t * vertex_count + v; zeros where a target has no deltas), one float
// weight per target; summed in target order.
struct SkinPush {
  uint vertex_count;
  uint influences;
  uint has_normals;          // 0: normals are not skinned (output left untouched)
  uint use_normal_matrices;  // 0: mat3(skin matrix) as in the CPU fast path
  uint morph_targets;        // 0: no morphing (delta and weight buffers not read)
  uint padding0;
  uint padding1;
  uint padding2;
};

// ---- the soft-GI frame (gbuffer, receivers, shadow_gather, exponentiate, indirect, upsample,
// composite). World space: glTF (+Y up, meters). Radiance linear RGB; "irradiance" E = ∫ L cos
// (not divided by π); receiver radiance = albedo / π · E.
PROXYGI_CONST(uint, kFrameLocalSize, 8u);      // compute passes run 8×8 workgroups
PROXYGI_CONST(uint, kMaxProxies, 1024u);       // per frame, all characters together
PROXYGI_CONST(uint, kIndirectOrder, 3u);       // indirect light is order 3 (paper §5)
PROXYGI_CONST(uint, kMaxShCoefficients, 36u);  // order 6

// One proxy sphere in world space, streamed every frame through the ring buffer.
struct ProxySphere {
  vec4 center_radius;  // xyz center (m), w radius (m)
  vec4 albedo;         // linear rgb, w unused
};

// Per-frame constants (uniform buffer, std140: only vec4/mat4/uvec4 members).
struct FrameConstants {
  mat4 view_projection;       // world → Vulkan clip space
  mat4 inverse_view_projection;  // clip → world (background rays)
  vec4 eye_position;          // xyz eye (m)
  vec4 eye_forward;           // xyz unit image-plane normal E: eye depth z = (p − e)·E
  uvec4 sizes;                // display width, height, receiver width, height
  uvec4 counts;               // proxy count, receiver scale k, SH order, upsample mode (0 bilateral, 1 bilinear,
                              // kCompositeDisplayIrradiance: the vertex method's G-buffer holds E already)
  vec4 shadow;                // η shadows, η indirect, HYB τ, log-table rows
  vec4 tables;                // OL max norm, OL rows, visibility-table rows, LH cube face size
  vec4 output_params;         // exposure multiplier, tonemap (0 aces, 1 reinhard, 2 clamp), bilateral ε (m), indirect on (1/0)
  vec4 irradiance_sh[3u * kIndirectOrder * kIndirectOrder];  // L̃ = L * clamped cosine, order 3, r then g then b; x used
};

// Push constants of composite.comp.
struct CompositePush {
  uint environment_width;   // equirectangular map (sh/environment.h convention), vec4 texels
  uint environment_height;
  uint padding0;
  uint padding1;
};

// counts.w of the vertex method: upsample_composite reads display-resolution irradiance from the
// G-buffer's second target (gbuffer.frag with VERTEX_IRRADIANCE writes it there, not the normal).
PROXYGI_CONST(uint, kCompositeDisplayIrradiance, 2u);

// Push constants of gbuffer.vert/frag: one draw per primitive.
// Albedo = base_color.rgb × texture(binding 5) at uv' = (u·xyz, v·xyz) of (uv, 1): the rows of
// the material's KHR_texture_transform matrix (gpu/material_textures.h).
struct GbufferPush {
  vec4 base_color;       // linear rgba factor
  vec4 uv_transform_u;   // u' = dot(uv_transform_u.xyz, vec3(uv, 1))
  vec4 uv_transform_v;   // v' = dot(uv_transform_v.xyz, vec3(uv, 1))
  uint has_uvs;          // 0: no TEXCOORD_0, uv = (0, 0) and binding 4 is not read
  uint receiver_offset;  // vertex method: the receiver of this draw's vertex 0 (shaded[offset + i])
  uint flip_normals;  // 1: negative-determinant transform (not used by skinned meshes)
  uint padding0;
};

// Push constants of vertex_receivers.comp: one dispatch per draw, vertices become receivers
// offset .. offset + vertex_count − 1.
struct VertexReceiversPush {
  uint vertex_count;
  uint receiver_offset;
  uint padding0;
  uint padding1;
};

// One receiver (receiver buffer, 1/k of display resolution).
struct Receiver {
  vec4 position_depth;  // xyz world point p, w eye depth (0: no receiver here)
  vec4 normal;          // xyz unit normal N, w unused
};

#ifdef __cplusplus
static_assert(sizeof(TestPatternPush) == 16);
static_assert(sizeof(ProxySphere) == 32);
static_assert(sizeof(FrameConstants) == 128 + 16 * 7 + 16 * 27);
static_assert(sizeof(GbufferPush) == 64);
static_assert(sizeof(Receiver) == 32);
static_assert(sizeof(CompositePush) == 16);
static_assert(sizeof(SkinPush) == 32);
static_assert(sizeof(VertexReceiversPush) == 16);
}  // namespace proxygi::gpu_layout
#endif

#endif
