#include "apps/frame_timing.h"

#include <chrono>

namespace proxygi::app {

Result<double> time_pipelined_frames(gpu::SceneRenderer& renderer, int first, int frames) {
  for (int warm = 0; warm < 2; ++warm)
    if (auto done = renderer.render(first + warm); !done) return done.error();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) {
    const int frame = first + 2 + i;
    if (Status begun = renderer.begin_frame(frame); !begun) return begun.error();
    if (i > 0)
      if (auto done = renderer.finish_frame(frame - 1); !done) return done.error();
  }
  if (auto done = renderer.finish_frame(first + 1 + frames); !done) return done.error();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / frames;
}

}  // namespace proxygi::app
