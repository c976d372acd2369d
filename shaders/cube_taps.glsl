// The four texels around N in the cube face it hits (first coefficient index of each) and the
// bilinear fractions, for cubes of `size`² texels per face and `count` values per texel stored
// channel after channel (sh/environment.h layout). CPU twin: render::lookup_lighting_cube.
// Used by lighting_cube.glsl (LH cubes) and indirect.comp (sender light cubes).
#ifndef PROXYGI_CUBE_TAPS_GLSL
#define PROXYGI_CUBE_TAPS_GLSL

struct CubeTaps {
  int t00, t10, t01, t11;
  float fx, fy;
};
CubeTaps cube_map_taps(int size, int count, int channel, vec3 n) {
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
  float u = clamp((0.5 * (sc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  float v = clamp((0.5 * (tc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  int x0 = min(int(u), size - 1), y0 = min(int(v), size - 1);
  int x1 = min(x0 + 1, size - 1), y1 = min(y0 + 1, size - 1);
  int channel_base = channel * 6 * size * size * count;
  CubeTaps taps;
  taps.fx = u - float(x0);
  taps.fy = v - float(y0);
  taps.t00 = channel_base + ((face * size + y0) * size + x0) * count;
  taps.t10 = channel_base + ((face * size + y0) * size + x1) * count;
  taps.t01 = channel_base + ((face * size + y1) * size + x0) * count;
  taps.t11 = channel_base + ((face * size + y1) * size + x1) * count;
  return taps;
}

#endif
