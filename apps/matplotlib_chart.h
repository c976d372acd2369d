#pragma once
// Charts drawn by matplotlib under /usr/bin/python3 (Debian's python3-matplotlib installs there,
// not for a pyenv python3). The script travels in an environment variable, the data as JSON on
// stdin, and the PNG is written through a temporary file, so a failed run leaves no partial chart.
#include <string>

#include <nlohmann/json.hpp>

#include "base/result.h"

namespace proxygi::app {

// Runs `script` with argv[1] = the PNG path to write and `data` on stdin.
Status draw_matplotlib_chart(const std::string& script, const nlohmann::json& data, const std::string& png_path);

}  // namespace proxygi::app
