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
struct SkinPush {
  uint vertex_count;
  uint influences;
  uint has_normals;          // 0: normals are not skinned (output left untouched)
  uint use_normal_matrices;  // 0: mat3(skin matrix) as in the CPU fast path
};

#ifdef __cplusplus
static_assert(sizeof(TestPatternPush) == 16);
static_assert(sizeof(SkinPush) == 16);
}  // namespace proxygi::gpu_layout
#endif

#endif
