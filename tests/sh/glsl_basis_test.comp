#version 450
// Compiles the generated SH GLSL (basis orders 1-8, products and squares 3-6) with glslang so a
// broken generator fails the build's tests. The GPU-vs-CPU comparison comes with the passes.
#extension GL_GOOGLE_include_directive : require
#include "sh/sh_basis.glsl"
#include "sh/sh_product.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Output { float values[]; };

void main() {
  const vec3 dir = normalize(vec3(0.3, -0.5, 0.8));
  float b1[1]; sh_eval_basis_1(dir, b1);
  float b2[4]; sh_eval_basis_2(dir, b2);
  float b3[9]; sh_eval_basis_3(dir, b3);
  float b4[16]; sh_eval_basis_4(dir, b4);
  float b5[25]; sh_eval_basis_5(dir, b5);
  float b6[36]; sh_eval_basis_6(dir, b6);
  float b7[49]; sh_eval_basis_7(dir, b7);
  float b8[64]; sh_eval_basis_8(dir, b8);
  float p3[9]; sh_product_3(b3, b3, p3); sh_square_3(p3, b3);
  float p4[16]; sh_product_4(b4, b4, p4); sh_square_4(p4, b4);
  float p5[25]; sh_product_5(b5, b5, p5); sh_square_5(p5, b5);
  float p6[36]; sh_product_6(b6, b6, p6); sh_square_6(p6, b6);
  values[0] = b1[0] + b2[3] + b3[8] + b4[15] + b5[24] + b6[35] + b7[48] + b8[63];
}
