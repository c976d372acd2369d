// Shared by the frame's compute passes: the frame constants, the tangent-plane rules and table
// lookups. CPU twins: sh::proxy_at_receiver (src/sh/tangent_plane.h) and src/render/shading.cpp
// (keep identical).
#ifndef PROXYGI_FRAME_COMMON_GLSL
#define PROXYGI_FRAME_COMMON_GLSL

#include "shared/layouts.h"

const float kPi = 3.14159265358979;
const float kSqrtFourPi = 3.5449077018110318;

float zonal_scale(int band) { return sqrt(4.0 * kPi / float(2 * band + 1)); }

// Tangent-plane rules (notes/sh-math.md §5). Returns false when the sphere is skipped; else the
// unit direction to the adjusted center and s = min(r'/|c' − p|, 1).
bool proxy_seen_from(vec3 p, vec3 normal, vec3 center, float radius, out vec3 direction, out float sine) {
  direction = vec3(0.0, 1.0, 0.0);
  sine = 0.0;
  vec3 to_center = center - p;
  float height = dot(to_center, normal);
  if (height <= -radius) return false;
  if (dot(to_center, to_center) < radius * radius && height <= 0.0) return false;
  vec3 seen_center = center;
  float seen_radius = radius;
  if (height < radius) {
    seen_center = center + normal * (0.5 * (radius - height));
    seen_radius = 0.5 * (radius + height);
    if (height <= 0.0) {
      float circle = sqrt(max(radius * radius - height * height, 0.0));
      vec3 foot = center - height * normal;
      float factor = circle > 0.0 ? min(1.0, (length(p - foot) - circle) / circle) : 1.0;
      if (factor <= 0.0) return false;
      seen_radius *= factor;
    }
  }
  vec3 offset = seen_center - p;
  float distance_to_center = length(offset);
  if (distance_to_center <= 0.0 || seen_radius <= 0.0) return false;
  direction = offset / distance_to_center;
  sine = min(seen_radius / distance_to_center, 1.0);
  return true;
}

// Linear interpolation in a ZH table (sh/occlusion_tables.h ZonalTable layout): `rows` rows over
// s ∈ [0, 1], `order` floats a row. Declared by each shader as a macro over its buffer name.
#define ZONAL_LOOKUP(table, rows, order, s, band, out_value)                      \
  {                                                                             \
    float position_ = clamp(s, 0.0, 1.0) * float((rows) - 1);                   \
    int row_ = min(int(position_), (rows) - 2);                                 \
    float t_ = position_ - float(row_);                                         \
    float low_ = table[row_ * (order) + (band)];                                \
    float high_ = table[(row_ + 1) * (order) + (band)];                         \
    out_value = low_ + t_ * (high_ - low_);                                     \
  }

#endif
