#pragma once
// CPU twin of the G-buffer's base color texture lookup (gbuffer.frag), also the reference path
// tracer's texel filter (ref/embree_scene.h): glTF uv (0, 0) is the top-left corner of the
// image; texel i of n covers [i, i + 1) / n (Vulkan's convention, texel centers at (i + ½) / n);
// wrap and filter as Vulkan addresses and filters one mip level. Texels are linear RGB (sRGB
// codes decoded first, as a VK_FORMAT_R8G8B8A8_SRGB image is decoded before filtering).
#include <span>

#include <glm/glm.hpp>

#include "anim/character.h"

namespace proxygi::render {

// The material's KHR_texture_transform applied to a vertex uv: (M * vec3(uv, 1)).xy.
glm::vec2 transform_uv(const glm::mat3& transform, const glm::vec2& uv);

// The texel index that integer coordinate i (any sign) addresses on an axis of n texels.
int wrap_texel(int i, int n, anim::TextureWrap wrap);

// One level, nearest or bilinear, at uv. texels: width × height, row-major, top row first.
glm::vec3 sample_texels(std::span<const glm::vec3> texels, int width, int height, const glm::vec2& uv,
                        anim::TextureWrap wrap_s, anim::TextureWrap wrap_t, anim::TextureFilter filter);

// Mean linear color of an RGBA8 sRGB image (alpha ignored): the albedo a textured material
// falls back to where its texture cannot be sampled (a texCoord set other than 0).
glm::vec3 mean_linear_color(const anim::Image& image);

}  // namespace proxygi::render
