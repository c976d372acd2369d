// LH(N) lookups in the per-channel cube maps (sh/environment.h layout; CPU twin
// render::lookup_lighting_cube). Include after declaring `frame` (FrameConstants: tables.w is
// the face size) and the `lighting_cube` float buffer, with SH_COUNT defined. `channel` counts
// cubes: 0..2 the environment's r, g, b, kGroundLitCubes + 0..2 the ground-lit ones.
#ifndef PROXYGI_LIGHTING_CUBE_GLSL
#define PROXYGI_LIGHTING_CUBE_GLSL

// The first cube of the set lighting a receiver at p (CPU twin render::lighting_cube_set):
// receivers above the ground plane see the lit ground below their horizon.
int lighting_cube_set(vec3 p) { return p.y > kGroundBounceMinHeight ? int(kGroundLitCubes) : 0; }

// The four texels around N in the cube face it hits (first coefficient index of each) and the
// bilinear fractions: shared by both lookups below.
struct CubeTaps {
  int t00, t10, t01, t11;
  float fx, fy;
};
CubeTaps lighting_cube_taps(int channel, vec3 n) {
  vec3 a = abs(n);
  int face;
  float sc, tc, major;
  if (a.x >= a.y && a.x >= a.z) {
    face = n.x >= 0.0 ? 0 : 1; major = a.x; sc = n.x >= 0.0 ? -n.z : n.z; tc = -n.y;
  } else if (a.y >= a.z) {
    face = n.y >= 0.0 ? 2 : 3; major = a.y; sc = n.x; tc = n.y >= 0.0 ? n.z : -n.z;
  } else {
    face = n.z >= 0.0 ? 4 : 5; major = a.z; sc = n.z >= 0.0 ? n.x : -n.x; tc = -n.y;
  }
  int size = int(frame.lighting_cube_face_size);
  float u = clamp((0.5 * (sc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  float v = clamp((0.5 * (tc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  int x0 = min(int(u), size - 1), y0 = min(int(v), size - 1);
  int x1 = min(x0 + 1, size - 1), y1 = min(y0 + 1, size - 1);
  int channel_base = channel * 6 * size * size * SH_COUNT;
  CubeTaps taps;
  taps.fx = u - float(x0);
  taps.fy = v - float(y0);
  taps.t00 = channel_base + ((face * size + y0) * size + x0) * SH_COUNT;
  taps.t10 = channel_base + ((face * size + y0) * size + x1) * SH_COUNT;
  taps.t01 = channel_base + ((face * size + y1) * size + x0) * SH_COUNT;
  taps.t11 = channel_base + ((face * size + y1) * size + x1) * SH_COUNT;
  return taps;
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
