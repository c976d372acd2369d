#pragma once
// MP4 from the recorded PNG frames through the ffmpeg command-line tool (libx264, yuv420p,
// CRF 18). ffmpeg writes to a temporary name in the output folder that is renamed to
// DIR/video.mp4 only when it succeeds, so an interrupted encode never leaves a broken video.
#include <filesystem>
#include <optional>

#include "base/result.h"

namespace proxygi::app {

// The first executable named `program` on $PATH (or `program` itself when it contains '/').
std::optional<std::filesystem::path> find_program(const std::string& program);

struct VideoJob {
  std::filesystem::path ffmpeg;  // from find_program("ffmpeg")
  std::filesystem::path dir;     // holds frame_%05d.png
  int first_frame = 0;
  int frame_count = 0;
  double fps = 24.0;
};

// DIR/video.mp4
std::filesystem::path video_file(const std::filesystem::path& dir);

// Runs ffmpeg on frames first_frame .. first_frame + frame_count - 1 (all must exist). Errors
// name ffmpeg's exit status.
Status encode_video(const VideoJob& job);

}  // namespace proxygi::app
