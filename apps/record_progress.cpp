#include "apps/record_progress.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>

namespace proxygi::app {
namespace {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const long total = std::lround(seconds);
  char text[32];
  if (total >= 3600) std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else std::snprintf(text, sizeof(text), "%02ld:%02ld", total / 60, total % 60);
  return text;
}

}  // namespace

std::size_t peak_resident_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return std::size_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

RecordProgress::RecordProgress(int to_render, int skipped, std::FILE* stream)
    : stream_(stream), terminal_(isatty(fileno(stream)) != 0), to_render_(to_render), skipped_(skipped),
      start_(std::chrono::steady_clock::now()) {}

double RecordProgress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double RecordProgress::frames_per_second() const {
  const double wall = wall_seconds();
  return wall > 0.0 ? double(rendered_) / wall : 0.0;
}

void RecordProgress::frame_rendered(int frame, std::size_t proxies, double cpu_prepare_ms) {
  ++rendered_;
  total_prepare_ms_ += cpu_prepare_ms;
  total_proxies_ += double(proxies);
  const double fps = frames_per_second();
  const double eta = fps > 0.0 ? double(to_render_ - rendered_) / fps : -1.0;
  std::fprintf(stream_, "%sframe %d: %d of %d, %.2f fps, ETA %s%s", terminal_ ? "\r" : "", frame, rendered_,
               to_render_, fps, format_duration(eta).c_str(), terminal_ ? "\033[K" : "\n");
  std::fflush(stream_);
}

void RecordProgress::finish() {
  if (terminal_ && rendered_ > 0) std::fputc('\n', stream_);
  const double mean_ms = rendered_ > 0 ? 1000.0 * wall_seconds() / rendered_ : 0.0;
  const double mean_prepare_ms = rendered_ > 0 ? total_prepare_ms_ / rendered_ : 0.0;
  const double mean_proxies = rendered_ > 0 ? total_proxies_ / rendered_ : 0.0;
  std::fprintf(stream_,
               "record: %d frames rendered, %d skipped, %.2f s wall, %.2f fps, %.1f ms/frame mean (CPU prepare "
               "%.2f ms), %.1f proxies mean, peak RSS %.1f MiB\n",
               rendered_, skipped_, wall_seconds(), frames_per_second(), mean_ms, mean_prepare_ms, mean_proxies,
               double(peak_resident_bytes()) / (1024.0 * 1024.0));
  std::fflush(stream_);
}

}  // namespace proxygi::app
