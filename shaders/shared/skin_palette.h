// Skin palettes of skin.comp, shared by GLSL and C++: a skin's matrices are read from a uniform
// buffer when they fit one (on llvmpipe cheaper than a storage buffer) and from a storage buffer
// (variant "skin.comp:storage_palette") beyond. Column-major mat4 per joint, in both.
#ifndef PROXYGI_SHADERS_SHARED_SKIN_PALETTE_H
#define PROXYGI_SHADERS_SHARED_SKIN_PALETTE_H

#include "layouts.h"

#ifdef __cplusplus
namespace proxygi::gpu_layout {
#endif

// Most joints a uniform palette holds: 1024 mat4 = 64 KiB, the maxUniformBufferRange of lavapipe
// and NVIDIA (on a device with less, every palette takes the storage variant).
PROXYGI_CONST(uint, kSkinUniformPaletteJoints, 1024u);
PROXYGI_CONST(uint, kSkinUniformPaletteBytes, kSkinUniformPaletteJoints * 64u);

#ifdef __cplusplus
static_assert(kSkinUniformPaletteBytes == kSkinUniformPaletteJoints * sizeof(mat4));
}  // namespace proxygi::gpu_layout
#endif

#endif
