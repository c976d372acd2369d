#pragma once
// Minimal leveled logging to stderr. Libraries log facts a user may want (chosen device,
// rejected devices, cache hits); errors travel as Result values, not as log lines.
#include <cstdio>
#include <string>

namespace proxygi {

enum class LogLevel { quiet = 0, info = 1, debug = 2 };

LogLevel log_level();
void set_log_level(LogLevel level);

void log_info(const std::string& line);
void log_debug(const std::string& line);
void log_warning(const std::string& line);  // always printed, prefixed "warning: "

}  // namespace proxygi
