#pragma once
// An X server of the test's own (Xvfb, Debian package xvfb) for the window tests: started on a
// free display number, DISPLAY pointed at it, stopped at the end. When Xvfb is missing or does
// not come up, available() is false and the tests skip (GTEST_SKIP) instead of failing.
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace proxygi::view::testing {

class Xvfb {
 public:
  Xvfb() {
    for (int attempt = 0; attempt < 20 && pid_ <= 0; ++attempt) {
      const int display = 100 + int((getpid() + attempt * 37) % 800);
      if (std::filesystem::exists("/tmp/.X" + std::to_string(display) + "-lock")) continue;
      start(display);
    }
  }
  ~Xvfb() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;

  bool available() const { return pid_ > 0; }
  const std::string& why_not() const { return why_not_; }

 private:
  void start(int display) {
    const std::string name = ":" + std::to_string(display);
    const pid_t pid = fork();
    if (pid == 0) {
      execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp", nullptr);
      _exit(127);
    }
    if (pid < 0) {
      why_not_ = "fork failed";
      return;
    }
    const std::string socket = "/tmp/.X11-unix/X" + std::to_string(display);
    for (int i = 0; i < 100; ++i) {  // up to 5 s
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        why_not_ = WEXITSTATUS(status) == 127 ? "Xvfb is not installed (Debian package xvfb)" : "Xvfb exited";
        return;
      }
      if (std::filesystem::exists(socket)) {
        pid_ = pid;
        setenv("DISPLAY", name.c_str(), 1);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    why_not_ = "Xvfb did not start within 5 s";
  }

  pid_t pid_ = -1;
  std::string why_not_;
};

}  // namespace proxygi::view::testing
