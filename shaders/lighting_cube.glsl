// LH(N) lookups in the per-channel cube maps (sh/environment.h layout; CPU twin
// render::lookup_lighting_cube). Include after declaring `frame` (FrameConstants: tables.w is
// the face size) and the `lighting_cube` float buffer, with SH_COUNT defined. `channel` counts
// cubes: 0..2 the environment's r, g, b, kGroundLitCubes + 0..2 the ground-lit ones.
#ifndef PROXYGI_LIGHTING_CUBE_GLSL
#define PROXYGI_LIGHTING_CUBE_GLSL

// The first cube of the set lighting a receiver at p (CPU twin render::lighting_cube_set):
// receivers above the ground plane see the lit ground below their horizon.
int lighting_cube_set(vec3 p) { return p.y > kGroundBounceMinHeight ? int(kGroundLitCubes) : 0; }

#include "cube_taps.glsl"

CubeTaps lighting_cube_taps(int channel, vec3 n) {
  return cube_map_taps(int(frame.lighting_cube_face_size), SH_COUNT, channel, n);
}

// Coefficient i of LH(N), bilinear within the face.
float lighting_cube_coefficient(CubeTaps taps, int i) {
  float top = lighting_cube[taps.t00 + i] + taps.fx * (lighting_cube[taps.t10 + i] - lighting_cube[taps.t00 + i]);
  float bottom = lighting_cube[taps.t01 + i] + taps.fx * (lighting_cube[taps.t11 + i] - lighting_cube[taps.t01 + i]);
  return top + taps.fy * (bottom - top);
}

// LH(N) of one channel, bilinear within the cube face N hits (sh/environment.h layout).
void lighting_lookup(int channel, vec3 n, out float lh[SH_COUNT]) {
  CubeTaps taps = lighting_cube_taps(channel, n);
  for (int i = 0; i < SH_COUNT; ++i) lh[i] = lighting_cube_coefficient(taps, i);
}

// DC coefficient of LH(N) only: enough when the visibility is the constant a(0)·1.
float lighting_lookup_dc(int channel, vec3 n) { return lighting_cube_coefficient(lighting_cube_taps(channel, n), 0); }

#endif
