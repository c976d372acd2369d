#version 460
// Raster shadow splat (frame step 4), vertex stage: instance i draws proxy i's coarse bounding
// mesh of its sphere of influence (center c, radius η·r; the mesh is a unit-sphere polyhedron
// scaled so its faces lie outside the unit sphere). Only back faces are kept (the pipeline culls
// front faces): with the depth test GREATER against the receivers' depth, a receiver gets a
// fragment exactly when it lies in front of the back surface (paper §4.1); the fragment stage
// rejects the ones in front of the sphere.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kSplatBindFrame) uniform Frame { FrameConstants frame; };
layout(std140, set = 0, binding = kSplatBindProxies) uniform Proxies { ProxySphere proxies[kMaxProxies]; };
layout(std430, set = 0, binding = kSplatBindBoundingMesh) readonly buffer BoundingMesh { vec4 bounding_mesh[]; };  // triangle list

layout(location = 0) flat out vec4 sphere;  // proxy center (m), radius (m)
layout(location = 1) flat out float weight; // the LOD cross-fade's share of its log occlusion (1: whole)

void main() {
  sphere = proxies[gl_InstanceIndex].center_radius;
  weight = proxies[gl_InstanceIndex].albedo.w;
  vec3 world = sphere.xyz + (frame.shadow_eta * sphere.w) * bounding_mesh[gl_VertexIndex].xyz;
  gl_Position = frame.view_projection * vec4(world, 1.0);
}
