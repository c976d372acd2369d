#pragma once
// Progress of `proxygi record` on stderr: one updating line ('\r') when stderr is a terminal,
// else one line per frame (logs, CI, Slurm), then a summary line.
#include <chrono>
#include <cstddef>
#include <cstdio>

namespace proxygi::app {

// Peak resident set size of this process so far, in bytes (getrusage ru_maxrss).
std::size_t peak_resident_bytes();

class RecordProgress {
 public:
  // `to_render`: frames this run will render; `skipped`: frames already on disk.
  RecordProgress(int to_render, int skipped, std::FILE* stream = stderr);

  // Call once per rendered frame as its files are written; `proxies` and `cpu_prepare_ms` from
  // the renderer's frame statistics. Time starts at construction: build it after set-up.
  void frame_rendered(int frame, std::size_t proxies, double cpu_prepare_ms);
  // The summary: frames rendered/skipped, wall time, fps, mean wall ms per frame (frames
  // overlap in flight, so this is throughput), mean CPU prepare ms, mean proxies, peak RSS.
  void finish();

  double wall_seconds() const;
  double frames_per_second() const;

 private:
  std::FILE* stream_;
  bool terminal_;
  int to_render_;
  int skipped_;
  int rendered_ = 0;
  double total_prepare_ms_ = 0.0;
  double total_proxies_ = 0.0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace proxygi::app
