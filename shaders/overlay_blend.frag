#version 460
// The viewer's cached UI overlay over the frame. The overlay holds what Dear ImGui drew over
// transparent black: premultiplied colour P and coverage A = 1 − Π(1 − αᵢ). The pipeline blends
// (ONE, ONE_MINUS_SRC_ALPHA), so frame' = P + (1 − A) · frame: the same "over" as drawing the
// layers onto the frame one by one. Texel for pixel (no filtering); drawn with fullscreen.vert,
// scissored to the overlay's covered rectangles. CPU twin: view::blend_overlay.
#extension GL_GOOGLE_include_directive : require
#include "shared/overlay_layouts.h"

layout(set = 0, binding = PROXYGI_OVERLAY_BIND_OVERLAY) uniform sampler2D overlay;
layout(location = 0) out vec4 color;

void main() { color = texelFetch(overlay, ivec2(gl_FragCoord.xy), 0); }
