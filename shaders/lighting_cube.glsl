// LH(N) lookups in the per-channel cube maps (sh/environment.h layout; CPU twin
// render::lookup_lighting_cube). Include after declaring `frame` (FrameConstants: tables.w is
// the face size) and the `lighting_cube` float buffer, with SH_COUNT defined.
#ifndef PROXYGI_LIGHTING_CUBE_GLSL
#define PROXYGI_LIGHTING_CUBE_GLSL

// LH(N) of one channel, bilinear within the cube face N hits (sh/environment.h layout).
void lighting_lookup(int channel, vec3 n, out float lh[SH_COUNT]) {
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
  int size = int(frame.tables.w);
  float u = clamp((0.5 * (sc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  float v = clamp((0.5 * (tc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  int x0 = min(int(u), size - 1), y0 = min(int(v), size - 1);
  int x1 = min(x0 + 1, size - 1), y1 = min(y0 + 1, size - 1);
  float fx = u - float(x0), fy = v - float(y0);
  int channel_base = channel * 6 * size * size * SH_COUNT;
  int t00 = channel_base + ((face * size + y0) * size + x0) * SH_COUNT;
  int t10 = channel_base + ((face * size + y0) * size + x1) * SH_COUNT;
  int t01 = channel_base + ((face * size + y1) * size + x0) * SH_COUNT;
  int t11 = channel_base + ((face * size + y1) * size + x1) * SH_COUNT;
  for (int i = 0; i < SH_COUNT; ++i) {
    float top = lighting_cube[t00 + i] + fx * (lighting_cube[t10 + i] - lighting_cube[t00 + i]);
    float bottom = lighting_cube[t01 + i] + fx * (lighting_cube[t11 + i] - lighting_cube[t01 + i]);
    lh[i] = top + fy * (bottom - top);
  }
}

// DC coefficient of LH(N) only: enough when the visibility is the constant a(0)·1.
float lighting_lookup_dc(int channel, vec3 n) {
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
  int size = int(frame.tables.w);
  float u = clamp((0.5 * (sc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  float v = clamp((0.5 * (tc / major + 1.0)) * float(size) - 0.5, 0.0, float(size - 1));
  int x0 = min(int(u), size - 1), y0 = min(int(v), size - 1);
  int x1 = min(x0 + 1, size - 1), y1 = min(y0 + 1, size - 1);
  float fx = u - float(x0), fy = v - float(y0);
  int channel_base = channel * 6 * size * size * SH_COUNT;
  float t00 = lighting_cube[channel_base + ((face * size + y0) * size + x0) * SH_COUNT];
  float t10 = lighting_cube[channel_base + ((face * size + y0) * size + x1) * SH_COUNT];
  float t01 = lighting_cube[channel_base + ((face * size + y1) * size + x0) * SH_COUNT];
  float t11 = lighting_cube[channel_base + ((face * size + y1) * size + x1) * SH_COUNT];
  float top = t00 + fx * (t10 - t00);
  float bottom = t01 + fx * (t11 - t01);
  return top + fy * (bottom - top);
}

#endif
