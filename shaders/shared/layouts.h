// Constants and struct layouts shared by C++ and GLSL. Included from GLSL with
// GL_GOOGLE_include_directive and from C++ (where the sizes are static_asserted against std430).
// Only scalar, vec4-aligned members: a struct here has the same bytes on both sides.
#ifndef PROXYGI_SHADERS_SHARED_LAYOUTS_H
#define PROXYGI_SHADERS_SHARED_LAYOUTS_H

#ifdef __cplusplus
#include <cstddef>
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
  uint joints;               // palette matrices per instance (instance i reads i × joints ..)
  uint instance_stride;      // output vertices per instance (≥ vertex_count; i × stride ..)
  uint padding0;
};

// ---- the soft-GI frame (gbuffer, receivers, shadow_gather, exponentiate, indirect, upsample,
// composite). World space: glTF (+Y up, meters). Radiance linear RGB; "irradiance" E = ∫ L cos
// (not divided by π); receiver radiance = albedo / π · E.
PROXYGI_CONST(uint, kFrameLocalSize, 8u);      // compute passes run 8×8 workgroups
PROXYGI_CONST(uint, kMaxProxies, 1024u);       // per frame, all characters together
PROXYGI_CONST(uint, kIndirectOrder, 3u);       // indirect light is order 3 (paper §5)
PROXYGI_CONST(uint, kMaxShCoefficients, 36u);  // order 6
// The LH cube buffer holds six cubes: r, g, b of the environment, then r, g, b of the ground-lit
// environment L' (render/frame_tables.h), read by receivers higher than kGroundBounceMinHeight
// (m) above the ground plane y = 0; the ground itself keeps the environment's cubes.
PROXYGI_CONST(uint, kGroundLitCubes, 3u);
PROXYGI_CONST(float, kGroundBounceMinHeight, 0.001f);
// HYB's blend toward the next squaring count starts at this fraction of τ (sh::kHybridBlendStart).
PROXYGI_CONST(float, kHybridBlendStart, 0.75f);

// One proxy sphere in world space, streamed every frame through the ring buffer.
struct ProxySphere {
  vec4 center_radius;  // xyz center (m), w radius (m)
  vec4 albedo;         // linear rgb, w the sphere's weight in the sums (render::Sphere::weight; 1 without LOD fades)
};

// Per-frame constants (uniform buffer, std140). Scalars come in groups of four so every group
// sits on a 16-byte boundary and the C++ struct has the same bytes as the GLSL block.
struct FrameConstants {
  mat4 view_projection;          // world → Vulkan clip space
  mat4 inverse_view_projection;  // clip → world (background rays)
  vec4 eye_position;             // xyz eye (m)
  vec4 eye_forward;              // xyz unit image-plane normal E: eye depth z = (p − e)·E
  uint display_width;            // pixels
  uint display_height;
  uint receiver_width;           // receivers (1/k of the display, or the vertex method's layout)
  uint receiver_height;
  uint proxy_count;              // spheres in the Proxies block
  uint receiver_scale;           // k
  uint sh_order;                 // n (the order-dependent shaders are compiled per order: checked)
  uint composite_mode;           // kCompositeBilateral, kCompositeBilinear or kCompositeDisplayIrradiance
  float shadow_eta;              // η of shadows (proxy radii)
  float indirect_eta;            // η of indirect light
  float hybrid_tau;              // HYB τ (float max: OL alone)
  float log_table_rows;          // rows of the log-occlusion table
  float optimal_linear_max_norm; // largest |f̂| the OL table covers
  float optimal_linear_rows;
  float visibility_table_rows;
  float lighting_cube_face_size; // LH cube texels per face edge
  float exposure;                // multiplier before the tonemap (2^EV)
  uint tonemap;                  // kTonemapAces, kTonemapReinhard or kTonemapClamp
  float bilateral_depth_epsilon; // ε of eq. 11 (tangent-plane distance / eye depth)
  uint indirect_enabled;         // 0: no bounce light
  uint debug_view;               // kDebugView*: what the composite writes (the viewer's views)
  uint tile_counts_valid;        // 1: the shadow pass wrote the TileCounts buffer (compute gather, AO)
  float occlusion_scale;         // direct[].w × this = visible fraction of the sphere (1/√4π SHEXP, 1 AO)
  uint padding_debug2;
  // VSGL (render.indirect_method vsgl): the L̃ = L * clamped cosine (order 3, r then g then b; x
  // used) that lights the vertex VPLs (vsgl_lights.comp), without the sun's share when the sun
  // variant is on (sh/vsgl_sun.h). The proxies' sender light is a table (kIndirectBindSenderLight).
  vec4 vsgl_sender_sh[3u * kIndirectOrder * kIndirectOrder];
  // The sun variant (render.vsgl_sun; rsm.vert/.frag, rsm_sums.comp), when rsm_toward_sun.w is 1:
  mat4 rsm_view_projection;          // world → the sun map's Vulkan clip space (sh::RsmView)
  mat4 rsm_inverse_view_projection;  // its inverse (partial origins)
  vec4 rsm_toward_sun;               // xyz s (world, unit), w 1: on this frame, 0: off
  vec4 rsm_texel_flux;               // rgb E_s a_t: the sun's power through one texel (W), a unused
};

// FrameConstants::composite_mode: how upsample_composite forms display-resolution irradiance.
PROXYGI_CONST(uint, kCompositeBilateral, 0u);
PROXYGI_CONST(uint, kCompositeBilinear, 1u);
// The vertex method: the G-buffer's second target already holds the interpolated irradiance
// (gbuffer.frag with VERTEX_IRRADIANCE writes it there, not the normal).
PROXYGI_CONST(uint, kCompositeDisplayIrradiance, 2u);
// FrameConstants::debug_view: the final frame, or one of its inputs in place of the radiance.
PROXYGI_CONST(uint, kDebugViewFinal, 0u);
PROXYGI_CONST(uint, kDebugViewAlbedo, 1u);      // G-buffer albedo, as display values
PROXYGI_CONST(uint, kDebugViewNormals, 2u);     // G-buffer normal, 0.5 + 0.5 n
PROXYGI_CONST(uint, kDebugViewIrradiance, 3u);  // E/π (direct + indirect light on white), tonemapped
PROXYGI_CONST(uint, kDebugViewReceivers, 4u);   // the nearest receiver's E/π, no upsampling: 1/k blocks
// These write the view's value to the HDR output (display: its tonemap or ramp); covered pixels
// only (the background stays the environment), not for the vertex method (final frame instead):
PROXYGI_CONST(uint, kDebugViewDirect, 5u);      // albedo/π · E_direct (the final frame = direct + indirect)
PROXYGI_CONST(uint, kDebugViewIndirect, 6u);    // albedo/π · E_indirect
PROXYGI_CONST(uint, kDebugViewOcclusion, 7u);   // visible fraction of the sphere, (O_p)_0/√4π (AO: A), in [0, 1]
// Every pixel: the proxies kept by its 8×8-receiver tile's culling (shadow η; HDR = the count),
// shown as a ramp over 0..proxy_count blended on the final frame. Where the shadow pass keeps no
// tile lists (raster splat, vertex method: tile_counts_valid 0) it shows the final frame.
PROXYGI_CONST(uint, kDebugViewHeatMap, 8u);
PROXYGI_CONST(uint, kDebugViewCount, 9u);
// FrameConstants::tonemap.
PROXYGI_CONST(uint, kTonemapAces, 0u);
PROXYGI_CONST(uint, kTonemapReinhard, 1u);
PROXYGI_CONST(uint, kTonemapClamp, 2u);

// Push constants of composite.comp.
struct CompositePush {
  uint environment_width;   // equirectangular map (sh/environment.h convention), vec4 texels
  uint environment_height;
  uint ldr_swap_red_blue;   // 1: the packed 8-bit frame in B, G, R, A byte order (FrameOutput)
  uint padding1;
};

// Push constants of supersample_resolve.comp (render.antialiasing).
struct SupersamplePush {
  uint width;             // display pixels; the samples are (width·factor) × (height·factor)
  uint height;
  uint factor;            // f samples per pixel per axis
  uint ldr_swap_red_blue; // 1: the packed 8-bit frame out in B, G, R, A byte order (FrameOutput)
};

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
// Read as rgba32f texels (upsample_composite.comp), receiver i is texels kReceiverTexels·i
// (position_depth) and kReceiverTexels·i + 1 (normal).
PROXYGI_CONST(uint, kReceiverTexels, 2u);

// One PRT triangle (prt::StaticTransferField): unit geometric normal on its vertex normals'
// side (w unused) and its vertices (xyz, w unused).
struct StaticTriangle {
  vec4 normal;
  uvec4 vertices;
};

// ---- VSGL bounce light (render.indirect_method vsgl; sh/vsgl.h is the CPU twin) ----
// vsgl_lights.comp stage 0: each character draw's triangles (or one of render.vsgl_lights index
// ranges of them, each its own light) are diffuse VPLs (centroid, summed vertex normals, area,
// flux = base color × max(E(N), 0) × area × the vertices' mean sender exposure, E from vsgl_sender_sh), summed per workgroup
// (kVsglGroupSize × kVsglTrianglesPerInvocation triangles) into one partial (positions relative
// to the group's first centroid); stage 1: one invocation per light sums its partials in order (shifted to the
// origin of its first) and fits the VSGL. indirect.comp:vsgl evaluates the lights per receiver.
PROXYGI_CONST(uint, kVsglMaxLights, 256u);      // characters × render.vsgl_lights per frame
PROXYGI_CONST(uint, kVsglGroupSize, 64u);       // invocations per workgroup (and lights per fit group)
PROXYGI_CONST(uint, kVsglTrianglesPerInvocation, 16u);  // a partial sums 64 × 16 triangles
// Character triangles beyond (kVsglMaxPartials − the sun map's partials) × 1024 are skipped.
PROXYGI_CONST(uint, kVsglMaxPartials, 20480u);
PROXYGI_CONST(float, kVsglDiffuseSharpness, 2.0);        // λ_d (sh::kDiffuseLobeSharpness)
PROXYGI_CONST(float, kVsglMinRelativeVariance, 1e-6);    // sh::kVsglMinRelativeVariance
PROXYGI_CONST(uint, kVsglStageSums, 0u);
PROXYGI_CONST(uint, kVsglStageFit, 1u);

// Sums of one workgroup of VPLs (sh::VsglSums relative to `origin`).
struct VsglPartial {
  vec4 origin_light;     // xyz origin (m), w the light (character) index as a float
  vec4 weight_axis;      // x Σ w, yzw Σ w ξ̄ (w = luminance of the flux, ξ̄ = λ_d/(λ_d+1) n)
  vec4 position_square;  // xyz Σ w (x − origin), w Σ w ‖x − origin‖²
  vec4 flux;             // rgb Σ flux, a unused
};
// One fitted VSGL (sh::Vsgl). Unused lights have zero amplitude.
struct VsglLight {
  vec4 axis_sharpness;   // xyz ξ_v, w λ_v
  vec4 amplitude;        // rgb c_v (flux / sr), a unused
  vec4 mean_variance;    // xyz μ_v (m), w σ_v² (m²)
};
// Push constants of vsgl_lights.comp.
struct VsglLightsPush {
  vec4 base_color;       // stage 0: the draw's linear albedo factor
  uint stage;            // kVsglStageSums or kVsglStageFit
  uint triangle_count;   // stage 0: triangles of the draw
  uint partial_offset;   // stage 0: partial of the draw's first workgroup
  uint light;            // stage 0: the draw's light index
  uint partial_count;    // stage 1: partials written
  uint light_count;      // stage 1: lights to fit (≤ kVsglMaxLights)
  uint first_triangle;   // stage 0: the draw's first triangle of this dispatch
  uint has_exposure;     // stage 0: 1 = scale each VPL by its vertices' mean exposure (binding
                         // kVsglBindExposure), 0 = the draw has none (exposure 1)
};

// ---- the sun variant of VSGL (render.vsgl_sun; sh/vsgl_sun.h is the CPU twin) ----
// rsm.vert/.frag draw the senders (each light's triangles, as vsgl_lights.comp splits them) into
// a kRsmSize² orthographic map from the sun: position (w = light + 1; 0: no sender), normal and
// flux = base color × E_s a_t (0 where n·s ≤ 0). rsm_sums.comp: one dispatch per light, each
// workgroup sums kVsglGroupSize × kRsmTexelsPerInvocation texels of that light into one
// VsglPartial (origin: the group's rows at mid depth), which vsgl_lights.comp's fit adds to the
// vertex VPLs' partials of the same light.
PROXYGI_CONST(uint, kRsmSize, 256u);                 // texels per side of the sun map
PROXYGI_CONST(uint, kRsmTexelsPerInvocation, 64u);
PROXYGI_CONST(uint, kRsmGroupsPerLight, kRsmSize * kRsmSize / (kVsglGroupSize * kRsmTexelsPerInvocation));
// Push constants of rsm.vert/.frag: one draw per light range.
struct RsmPush {
  vec4 base_color;  // linear albedo factor
  uint light;       // the light these triangles send through
  uint padding0;
  uint padding1;
  uint padding2;
};
// Push constants of rsm_sums.comp.
struct RsmSumsPush {
  uint light;
  uint partial_offset;  // the partial of the dispatch's first workgroup
  uint padding0;
  uint padding1;
};

// ---- descriptor bindings (set 0) of each shader: the GLSL declarations and the C++ passes'
// layouts and descriptor pushes both use these names, so a binding is numbered once ----
// receivers.comp
PROXYGI_CONST(uint, kReceiversBindFrame, 0u);
PROXYGI_CONST(uint, kReceiversBindPositionDepth, 1u);
PROXYGI_CONST(uint, kReceiversBindNormal, 2u);
PROXYGI_CONST(uint, kReceiversBindReceivers, 3u);
// shadow_gather.comp
PROXYGI_CONST(uint, kShadowBindFrame, 0u);
PROXYGI_CONST(uint, kShadowBindReceivers, 1u);
PROXYGI_CONST(uint, kShadowBindProxies, 2u);
PROXYGI_CONST(uint, kShadowBindLogTable, 3u);
PROXYGI_CONST(uint, kShadowBindLogOcclusion, 4u);
// Per 8×8-receiver tile (row-major over ceil(receiver_width / 8) tiles a row): how many proxies
// its culling kept. Written by shadow_gather.comp and ambient_occlusion.comp (lane 0 of a group).
PROXYGI_CONST(uint, kShadowBindTileCounts, 5u);
// exponentiate.comp
PROXYGI_CONST(uint, kExponentiateBindFrame, 0u);
PROXYGI_CONST(uint, kExponentiateBindReceivers, 1u);
PROXYGI_CONST(uint, kExponentiateBindLogOcclusion, 2u);
PROXYGI_CONST(uint, kExponentiateBindOptimalLinear, 3u);
PROXYGI_CONST(uint, kExponentiateBindLightingCube, 4u);
PROXYGI_CONST(uint, kExponentiateBindDirect, 5u);
// The static-transfer variants (render.static_transfer ratio, l1; static_transfer.glsl) also read
// the PRT field (prt/static_field.h): vertex positions, triangles, the lookup grid and the
// per-vertex records baked for the frame's lighting.
PROXYGI_CONST(uint, kExponentiateBindStaticPositions, 6u);  // vec4 per vertex: xyz world, m
PROXYGI_CONST(uint, kExponentiateBindStaticTriangles, 7u);  // StaticTriangle per triangle
PROXYGI_CONST(uint, kExponentiateBindStaticGrid, 8u);       // uint: header, cell starts, cell triangles
PROXYGI_CONST(uint, kExponentiateBindStaticRecords, 9u);    // float: prt::static_record_floats per vertex
PROXYGI_CONST(uint, kExponentiateBindStaticVisibility, 10u); // float: header, then n² per grid point
// The visibility grid buffer (prt/visibility_grid.h): kStaticVisibilityHeader floats (origin xyz,
// spacing in m, points per axis xyz as uint bits, 0), then the grid's values in its layout.
// Points per axis 0: no grid (every non-static receiver keeps l0).
PROXYGI_CONST(uint, kStaticVisibilityHeader, 8u);
// A grid point inside a static mesh holds this DC (and zeros); trilinear sampling leaves it out
// and renormalises over the valid corners, below this weight the receiver keeps l0.
PROXYGI_CONST(float, kStaticVisibilityInside, -1.0f);
PROXYGI_CONST(float, kStaticVisibilityMinWeight, 1e-4f);
// The grid buffer: kStaticGridHeader uints (origin xyz and cell edge as float bits, cells per
// axis xyz, then 0), the cell starts (cells + 1, offsets into the triangle lists, which start at
// kStaticGridHeader + cells + 1), then the triangle lists. Cells per axis 0: no static receivers.
PROXYGI_CONST(uint, kStaticGridHeader, 8u);
// When a receiver is static (prt::find_static_hit, static_transfer.glsl): within this distance
// (m) of a PRT triangle's plane, inside it with this barycentric slack, N · n_t above the cosine.
PROXYGI_CONST(float, kStaticHitDistance, 0.005f);
PROXYGI_CONST(float, kStaticHitBarycentricSlack, 1e-4f);
PROXYGI_CONST(float, kStaticHitCosine, 0.5f);
// indirect.comp (and indirect_exact.glsl)
PROXYGI_CONST(uint, kIndirectBindFrame, 0u);
PROXYGI_CONST(uint, kIndirectBindReceivers, 1u);
PROXYGI_CONST(uint, kIndirectBindProxies, 2u);
PROXYGI_CONST(uint, kIndirectBindVisibilityTable, 3u);
PROXYGI_CONST(uint, kIndirectBindDirect, 4u);
PROXYGI_CONST(uint, kIndirectBindIndirect, 5u);
PROXYGI_CONST(uint, kIndirectBindShaded, 6u);
PROXYGI_CONST(uint, kIndirectBindExactTable, 7u);
PROXYGI_CONST(uint, kIndirectBindVsglLights, 8u);  // read by the vsgl variant only
PROXYGI_CONST(uint, kIndirectBindSenderLight, 9u);  // L̃_N cube texels (render::FrameTables::sender_light_cube); not the vsgl variant
// vsgl_lights.comp
PROXYGI_CONST(uint, kVsglBindFrame, 0u);
PROXYGI_CONST(uint, kVsglBindPositions, 1u);
PROXYGI_CONST(uint, kVsglBindNormals, 2u);
PROXYGI_CONST(uint, kVsglBindIndices, 3u);
PROXYGI_CONST(uint, kVsglBindPartials, 4u);
PROXYGI_CONST(uint, kVsglBindLights, 5u);
PROXYGI_CONST(uint, kVsglBindExposure, 6u);  // float per vertex (ref/sender_exposure.h)
// rsm.vert/.frag
PROXYGI_CONST(uint, kRsmBindFrame, 0u);
PROXYGI_CONST(uint, kRsmBindPositions, 1u);
PROXYGI_CONST(uint, kRsmBindNormals, 2u);
// rsm_sums.comp
PROXYGI_CONST(uint, kRsmSumsBindFrame, 0u);
PROXYGI_CONST(uint, kRsmSumsBindPosition, 1u);
PROXYGI_CONST(uint, kRsmSumsBindNormal, 2u);
PROXYGI_CONST(uint, kRsmSumsBindFlux, 3u);
PROXYGI_CONST(uint, kRsmSumsBindPartials, 4u);
// upsample_composite.comp
PROXYGI_CONST(uint, kCompositeBindFrame, 0u);
PROXYGI_CONST(uint, kCompositeBindPositionDepth, 1u);
PROXYGI_CONST(uint, kCompositeBindNormal, 2u);
PROXYGI_CONST(uint, kCompositeBindReceivers, 3u);
PROXYGI_CONST(uint, kCompositeBindShaded, 4u);
PROXYGI_CONST(uint, kCompositeBindIrradiance, 5u);
PROXYGI_CONST(uint, kCompositeBindAlbedo, 6u);
PROXYGI_CONST(uint, kCompositeBindEnvironment, 7u);
PROXYGI_CONST(uint, kCompositeBindHdr, 8u);
PROXYGI_CONST(uint, kCompositeBindLdr, 9u);
PROXYGI_CONST(uint, kCompositeBindDirect, 10u);
PROXYGI_CONST(uint, kCompositeBindIndirect, 11u);
PROXYGI_CONST(uint, kCompositeBindTileCounts, 12u);
// ambient_occlusion.comp
PROXYGI_CONST(uint, kAoBindFrame, 0u);
PROXYGI_CONST(uint, kAoBindReceivers, 1u);
PROXYGI_CONST(uint, kAoBindProxies, 2u);
PROXYGI_CONST(uint, kAoBindLightingCube, 3u);
PROXYGI_CONST(uint, kAoBindDirect, 4u);
PROXYGI_CONST(uint, kAoBindIndirect, 5u);
PROXYGI_CONST(uint, kAoBindShaded, 6u);
PROXYGI_CONST(uint, kAoBindTileCounts, 7u);
// gbuffer.vert / gbuffer.frag
PROXYGI_CONST(uint, kGbufferBindFrame, 0u);
PROXYGI_CONST(uint, kGbufferBindPositions, 1u);
PROXYGI_CONST(uint, kGbufferBindNormals, 2u);
PROXYGI_CONST(uint, kGbufferBindShaded, 3u);
PROXYGI_CONST(uint, kGbufferBindUvs, 4u);
PROXYGI_CONST(uint, kGbufferBindBaseColorTexture, 5u);
// vertex_receivers.comp
PROXYGI_CONST(uint, kVertexReceiversBindPositions, 0u);
PROXYGI_CONST(uint, kVertexReceiversBindNormals, 1u);
PROXYGI_CONST(uint, kVertexReceiversBindReceivers, 2u);
// skin.comp
PROXYGI_CONST(uint, kSkinBindBindPositions, 0u);
PROXYGI_CONST(uint, kSkinBindBindNormals, 1u);
PROXYGI_CONST(uint, kSkinBindJoints, 2u);
PROXYGI_CONST(uint, kSkinBindWeights, 3u);
PROXYGI_CONST(uint, kSkinBindSkinMatrices, 4u);
PROXYGI_CONST(uint, kSkinBindNormalMatrices, 5u);
PROXYGI_CONST(uint, kSkinBindOutPositions, 6u);
PROXYGI_CONST(uint, kSkinBindOutNormals, 7u);
PROXYGI_CONST(uint, kSkinBindPositionDeltas, 8u);
PROXYGI_CONST(uint, kSkinBindNormalDeltas, 9u);
PROXYGI_CONST(uint, kSkinBindMorphWeights, 10u);
// the raster splat: receiver_depth.frag, shadow_splat.vert / .frag
PROXYGI_CONST(uint, kSplatBindFrame, 0u);
PROXYGI_CONST(uint, kSplatBindReceivers, 1u);
PROXYGI_CONST(uint, kSplatBindProxies, 2u);
PROXYGI_CONST(uint, kSplatBindBoundingMesh, 4u);
PROXYGI_CONST(uint, kSplatBindLogTable, 3u);
// supersample_resolve.comp
PROXYGI_CONST(uint, kSupersampleBindSampleHdr, 0u);
PROXYGI_CONST(uint, kSupersampleBindSampleLdr, 1u);
PROXYGI_CONST(uint, kSupersampleBindHdr, 2u);
PROXYGI_CONST(uint, kSupersampleBindLdr, 3u);
// splat_resolve.comp (targets at kResolveBindFirstTarget + i)
PROXYGI_CONST(uint, kResolveBindFrame, 0u);
PROXYGI_CONST(uint, kResolveBindLogOcclusion, 1u);
PROXYGI_CONST(uint, kResolveBindFirstTarget, 2u);

#ifdef __cplusplus
static_assert(sizeof(TestPatternPush) == 16);
static_assert(sizeof(ProxySphere) == 32);
static_assert(sizeof(StaticTriangle) == 32);
static_assert(sizeof(FrameConstants) == 128 + 16 * 8 + 16 * 27 + 128 + 32);
static_assert(offsetof(FrameConstants, rsm_view_projection) == 256 + 16 * 27);
static_assert(offsetof(FrameConstants, display_width) == 160 && offsetof(FrameConstants, vsgl_sender_sh) == 256);
static_assert(sizeof(GbufferPush) == 64);
static_assert(sizeof(Receiver) == 32 && sizeof(Receiver) == kReceiverTexels * sizeof(glm::vec4));
static_assert(sizeof(CompositePush) == 16);
static_assert(sizeof(SupersamplePush) == 16);
static_assert(sizeof(SkinPush) == 32);
static_assert(sizeof(VertexReceiversPush) == 16);
static_assert(sizeof(VsglPartial) == 64 && sizeof(VsglLight) == 48 && sizeof(VsglLightsPush) == 48);
static_assert(sizeof(RsmPush) == 32 && sizeof(RsmSumsPush) == 16);
}  // namespace proxygi::gpu_layout
#endif

#endif
