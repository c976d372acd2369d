// Layout of the viewer's UI overlay blend (overlay_blend.frag; C++ side src/view/overlay_blend_pass.h),
// shared by C++ and GLSL like layouts.h.
#ifndef PROXYGI_SHADERS_SHARED_OVERLAY_LAYOUTS_H
#define PROXYGI_SHADERS_SHARED_OVERLAY_LAYOUTS_H

// overlay_blend.frag, set 0: the cached overlay (premultiplied RGBA8, the target's size and
// format), a combined image sampler read with texelFetch.
#define PROXYGI_OVERLAY_BIND_OVERLAY 0

#endif
