#version 460
// Foundation test: a constant color the test reads back from an RGBA16F image.
layout(location = 0) out vec4 color;
void main() { color = vec4(0.25, 0.5, 0.75, 1.0); }
