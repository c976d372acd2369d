#version 460
// VSGL lights (render.indirect_method vsgl, frame step 6 before indirect.comp:vsgl), two stages:
//   kVsglStageSums: kVsglTrianglesPerInvocation triangles per invocation of one character draw
//     (or of one index range of it, render.vsgl_lights > 1), each a diffuse VPL at the
//     centroid x with normal n = normalize(n0 + n1 + n2), area A and flux Φ = albedo ·
//     max(E(n), 0) · A · e (E = Σ L̃_i y_i(n) of frame.vsgl_sender_sh, unshadowed; e the mean of
//     the vertices' sender exposures, ref/sender_exposure.h: 0 for a triangle buried inside another
//     body part; 1 without an exposure buffer); the workgroup's VPLs are summed serially
//     per invocation, then in a fixed tree (deterministic) into VsglPartial, positions relative
//     to the group's first centroid.
//   kVsglStageFit: invocation k sums the partials of light k in order (rsm_sums.comp's first,
//     render.vsgl_sun), each shifted to the origin of the first with weight, and fits ξ_v, λ_v, c_v, μ_v, σ_v² (sh::fit_vsgl).
// CPU twin: sh::triangle_light / sh::add_light / sh::fit_vsgl (src/sh/vsgl.h).
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"
#include "sh/sh_basis.glsl"

layout(local_size_x = kVsglGroupSize) in;
layout(std140, set = 0, binding = kVsglBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kVsglBindPositions) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = kVsglBindNormals) readonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = kVsglBindIndices) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = kVsglBindPartials) buffer Partials { VsglPartial partials[]; };
layout(std430, set = 0, binding = kVsglBindLights) writeonly buffer Lights { uvec4 light_count; VsglLight lights[]; };
layout(std430, set = 0, binding = kVsglBindExposure) readonly buffer Exposure { float exposure[]; };
layout(push_constant) uniform Push { VsglLightsPush push; };

shared vec4 shared_a[kVsglGroupSize];  // (w, w ξ̄)
shared vec4 shared_b[kVsglGroupSize];  // (w (x − o), w ‖x − o‖²)
shared vec4 shared_c[kVsglGroupSize];  // (flux, 0)
shared vec3 shared_origin;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);

// A(λ) = 2π (1 − e^{−2λ}) / λ, series near 0 (float has no expm1).
float sg_area(float sharpness) {
  if (sharpness < 1e-3) return 4.0 * kPi * (1.0 - sharpness + 2.0 / 3.0 * sharpness * sharpness);
  return 2.0 * kPi * (1.0 - exp(-2.0 * sharpness)) / sharpness;
}

// One triangle as a VPL: centroid, unit normal, flux (rgb).
void triangle_light(uint triangle, out vec3 center, out vec3 normal, out vec3 flux) {
  uint i0 = indices[3u * triangle], i1 = indices[3u * triangle + 1u], i2 = indices[3u * triangle + 2u];
  vec3 p0 = positions[i0].xyz, p1 = positions[i1].xyz, p2 = positions[i2].xyz;
  vec3 face = cross(p1 - p0, p2 - p0);
  float area = 0.5 * length(face);
  vec3 summed = normals[i0].xyz + normals[i1].xyz + normals[i2].xyz;
  normal = length(summed) > 0.0 ? normalize(summed) : (area > 0.0 ? face / (2.0 * area) : vec3(0.0, 1.0, 0.0));
  center = (p0 + p1 + p2) / 3.0;
  float basis[9];
  sh_eval_basis_3(normal, basis);
  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < 9; ++i)
    irradiance += basis[i] * vec3(frame.vsgl_sender_sh[i].x, frame.vsgl_sender_sh[9 + i].x, frame.vsgl_sender_sh[18 + i].x);
  float exposed = push.has_exposure != 0u ? (exposure[i0] + exposure[i1] + exposure[i2]) / 3.0 : 1.0;
  flux = push.base_color.rgb * max(irradiance, vec3(0.0)) * area * exposed;
}

void sum_triangles() {
  // The workgroup's triangles: kVsglTrianglesPerInvocation per invocation, strided by the group
  // size, summed serially (few barriers: lavapipe pays for each), then one tree over the group.
  uint local = gl_LocalInvocationID.x;
  uint group_first = gl_WorkGroupID.x * kVsglGroupSize * kVsglTrianglesPerInvocation;
  if (local == 0u) {  // a dispatched group always has its first triangle
    vec3 normal, flux;
    triangle_light(push.first_triangle + group_first, shared_origin, normal, flux);
  }
  barrier();
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  for (uint j = 0u; j < kVsglTrianglesPerInvocation; ++j) {
    uint t = group_first + j * kVsglGroupSize + local;
    if (t >= push.triangle_count) break;
    vec3 center, normal, flux;
    triangle_light(push.first_triangle + t, center, normal, flux);
    float w = dot(flux, kLuminance);
    vec3 relative = center - shared_origin;
    a += vec4(w, w * (kVsglDiffuseSharpness / (kVsglDiffuseSharpness + 1.0)) * normal);
    b += vec4(w * relative, w * dot(relative, relative));
    c += vec4(flux, 0.0);
  }
  shared_a[local] = a;
  shared_b[local] = b;
  shared_c[local] = c;
  barrier();
  for (uint stride = kVsglGroupSize / 2u; stride > 0u; stride /= 2u) {
    if (local < stride) {
      shared_a[local] += shared_a[local + stride];
      shared_b[local] += shared_b[local + stride];
      shared_c[local] += shared_c[local + stride];
    }
    barrier();
  }
  if (local == 0u) {
    VsglPartial partial;
    partial.origin_light = vec4(shared_origin, float(push.light));
    partial.weight_axis = shared_a[0];
    partial.position_square = shared_b[0];
    partial.flux = shared_c[0];
    partials[push.partial_offset + gl_WorkGroupID.x] = partial;
  }
}

void fit_light() {
  uint light = gl_GlobalInvocationID.x;
  if (light == 0u) light_count = uvec4(push.light_count, 0u, 0u, 0u);
  if (light >= kVsglMaxLights) return;  // (several workgroups of kVsglGroupSize lights)
  bool first = true;
  vec3 origin = vec3(0.0);
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  for (uint i = 0u; i < push.partial_count; ++i) {
    VsglPartial partial = partials[i];
    if (uint(partial.origin_light.w) != light) continue;
    if (first && partial.weight_axis.x > 0.0) origin = partial.origin_light.xyz, first = false;
    // Σ w (x − o) = P_j + W d, Σ w ‖x − o‖² = S_j + 2 d·P_j + W ‖d‖², d = o_j − o.
    vec3 d = partial.origin_light.xyz - origin;
    float weight = partial.weight_axis.x;
    b += vec4(partial.position_square.xyz + weight * d,
              partial.position_square.w + 2.0 * dot(d, partial.position_square.xyz) + weight * dot(d, d));
    a += partial.weight_axis;
    c += partial.flux;
  }
  VsglLight fitted;
  fitted.axis_sharpness = vec4(0.0, 0.0, 1.0, 0.0);
  fitted.amplitude = vec4(0.0);
  fitted.mean_variance = vec4(origin, 0.0);
  if (a.x > 0.0) {
    vec3 mean_axis = a.yzw / a.x;
    float len = min(length(mean_axis), 1.0 - 1e-6);
    float sharpness = len / (1.0 - len);
    fitted.axis_sharpness = vec4(len > 0.0 ? mean_axis / len : vec3(0.0, 0.0, 1.0), sharpness);
    fitted.amplitude = vec4(c.rgb / sg_area(sharpness), 0.0);
    vec3 mean = b.xyz / a.x;
    fitted.mean_variance = vec4(origin + mean, max(b.w / a.x - dot(mean, mean), 0.0));
  }
  lights[light] = fitted;
}

void main() {
  if (push.stage == kVsglStageSums) sum_triangles();
  else fit_light();
}
