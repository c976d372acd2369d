#include "base/log.h"

#include <atomic>

namespace proxygi {
namespace {
std::atomic<int> current_level{static_cast<int>(LogLevel::info)};
}

LogLevel log_level() { return static_cast<LogLevel>(current_level.load()); }
void set_log_level(LogLevel level) { current_level.store(static_cast<int>(level)); }

void log_info(const std::string& line) {
  if (current_level.load() >= static_cast<int>(LogLevel::info)) std::fprintf(stderr, "%s\n", line.c_str());
}
void log_debug(const std::string& line) {
  if (current_level.load() >= static_cast<int>(LogLevel::debug)) std::fprintf(stderr, "%s\n", line.c_str());
}
void log_warning(const std::string& line) { std::fprintf(stderr, "warning: %s\n", line.c_str()); }

}  // namespace proxygi
