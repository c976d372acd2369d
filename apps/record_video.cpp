#include "apps/record_video.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "base/atomic_file.h"

extern char** environ;

namespace proxygi::app {
namespace {

// Runs argv[0] with argv (no shell, so folder names need no quoting) and waits for it. Its stderr
// is captured into the error message (one line), not printed: it names the temporary file it
// writes, which write_via_temporary replaces by the user's path.
Status run_process(const std::vector<std::string>& argv) {
  std::vector<char*> raw;
  for (const std::string& arg : argv) raw.push_back(const_cast<char*>(arg.c_str()));
  raw.push_back(nullptr);
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return make_error(argv[0] + ": pipe: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, raw[0], &actions, nullptr, raw.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  if (spawned != 0) {
    close(pipe_fds[0]);
    return make_error(argv[0] + ": cannot start: " + std::strerror(spawned));
  }
  std::string output;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    output.append(buffer, std::size_t(n));
    if (output.size() > 8192) output.erase(0, output.size() - 8192);  // the end says what failed
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return make_error(argv[0] + ": waitpid: " + std::strerror(errno));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  for (char& c : output)
    if (c == '\n') c = ';';
  const std::string said = output.empty() ? std::string() : ": " + output;
  if (WIFSIGNALED(status)) return make_error(argv[0] + " was killed by signal " + std::to_string(WTERMSIG(status)) + said);
  return make_error(argv[0] + " exited with status " + std::to_string(WEXITSTATUS(status)) + said);
}

}  // namespace

std::optional<std::filesystem::path> find_program(const std::string& program) {
  if (program.find('/') != std::string::npos)
    return access(program.c_str(), X_OK) == 0 ? std::optional<std::filesystem::path>(program) : std::nullopt;
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string folders = path;
  std::size_t start = 0;
  while (start <= folders.size()) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::string folder = end > start ? folders.substr(start, end - start) : ".";
    const std::filesystem::path candidate = std::filesystem::path(folder) / program;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

std::filesystem::path video_file(const std::filesystem::path& dir) { return dir / "video.mp4"; }

Status encode_video(const VideoJob& job) {
  char rate[32];
  std::snprintf(rate, sizeof(rate), "%.9g", job.fps);
  return write_via_temporary(video_file(job.dir), [&](const std::filesystem::path& temporary) -> Status {
    // -f mp4: the temporary name has no .mp4 extension for ffmpeg to guess from.
    return run_process({job.ffmpeg.string(), "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
                        rate, "-start_number", std::to_string(job.first_frame), "-i",
                        (job.dir / "frame_%05d.png").string(), "-frames:v", std::to_string(job.frame_count),
                        "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-f", "mp4", temporary.string()});
  });
}

}  // namespace proxygi::app
