// The exact indirect operator (paper eq. 16/17, order 3) for one proxy at one receiver, included by
// indirect.comp's exact variant. CPU twin: render::exact_indirect_weights (src/render/
// exact_indirect.{h,cpp}, which explains the method; keep the two identical):
//   w = M(s)ᵀ H(R N) in the canonical frame (R takes d̂ to +z, rows b1, b2, d̂ of Duff et al.'s
//   branchless orthonormal basis), then W = R_sh⁻¹ w band by band: band 1 by R itself, band 2 by
//   evaluating at R ω_k for five fixed ω_k and the closed-form inverse of y_2m(ω_k).
// Then H(N) · I_c = W · L̃_c.
#ifndef PROXYGI_INDIRECT_EXACT_GLSL
#define PROXYGI_INDIRECT_EXACT_GLSL

// M(s) rows over s ∈ [0, 1] (sh::ExactIndirectTable): 81 floats a row, M_jk at j * 9 + k.
layout(std430, set = 0, binding = kIndirectBindExactTable) readonly buffer ExactIndirectTable { float exact_table[]; };

void exact_indirect_weights(float sine, vec3 direction, vec3 normal, out float weights[9]) {
  float sign_z = direction.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign_z + direction.z);
  float b = direction.x * direction.y * a;
  vec3 b1 = vec3(1.0 + sign_z * direction.x * direction.x * a, sign_z * b, -sign_z * direction.x);
  vec3 b2 = vec3(b, sign_z + direction.y * direction.y * a, -direction.y);

  // H(R N)
  float lobe[9];
  sh_eval_basis_3(vec3(dot(normal, b1), dot(normal, b2), dot(normal, direction)), lobe);
  const float cosine[3] = float[](0.886226925, 1.023326708, 0.495415912);
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m) lobe[l * (l + 1) + m] *= zonal_scale(l) * cosine[l];

  // w = M(s)ᵀ H(R N), rows interpolated like ZONAL_LOOKUP, over the 19 entries with m_j = m_k
  // (the others are zero: render::kExactIndirectEntries).
  const int entries[19] = int[](0, 2, 6, 18, 20, 24, 54, 56, 60, 10, 14, 46, 50, 30, 34, 66, 70, 40, 80);
  int rows = int(exact_table.length()) / 81;
  float position = clamp(sine, 0.0, 1.0) * float(rows - 1);
  int row = min(int(position), rows - 2);
  float t = position - float(row);
  int low = row * 81;
  float w[9];
  for (int k = 0; k < 9; ++k) w[k] = 0.0;
  for (int e = 0; e < 19; ++e) {
    int entry = entries[e];
    float m_low = exact_table[low + entry];
    float m_high = exact_table[low + 81 + entry];
    w[entry % 9] += lobe[entry / 9] * (m_low + t * (m_high - m_low));
  }

  weights[0] = w[0];
  vec3 u = vec3(-w[3], -w[1], w[2]);
  vec3 world = u.x * b1 + u.y * b2 + u.z * direction;
  weights[1] = -world.y;
  weights[2] = world.z;
  weights[3] = -world.x;

  const float half_sqrt2 = 0.70710678;
  vec3 fixed_directions[5] = vec3[](vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(half_sqrt2, half_sqrt2, 0.0),
                                    vec3(half_sqrt2, 0.0, half_sqrt2), vec3(0.0, half_sqrt2, half_sqrt2));
  float at[5];
  for (int k = 0; k < 5; ++k) {
    vec3 v = fixed_directions[k];
    float basis[9];
    sh_eval_basis_3(vec3(dot(v, b1), dot(v, b2), dot(v, direction)), basis);
    at[k] = 0.0;
    for (int c = 4; c < 9; ++c) at[k] += w[c] * basis[c];
  }
  const float band2_off = 1.092548430592079;
  const float band2_zonal = 0.315391565252520;
  const float band2_sector = 0.546274215296040;
  weights[4] = (2.0 * at[2] + at[1]) / band2_off;
  weights[5] = (-at[0] - 2.0 * at[4]) / band2_off;
  weights[6] = at[1] / (2.0 * band2_zonal);
  weights[7] = (at[0] + at[1] - 2.0 * at[3]) / band2_off;
  weights[8] = (at[0] + 0.5 * at[1]) / band2_sector;
}

#endif
