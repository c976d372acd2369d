#include "apps/matplotlib_chart.h"

#include <cstdio>
#include <cstdlib>

#include "base/atomic_file.h"

namespace proxygi::app {

Status draw_matplotlib_chart(const std::string& script, const nlohmann::json& data, const std::string& png_path) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
    return make_error("charts need matplotlib for /usr/bin/python3 (Debian: apt-get install python3-matplotlib)");
  const std::string text = data.dump();
  return write_via_temporary(png_path, [&](const std::filesystem::path& temporary) -> Status {
    if (temporary.string().find('\'') != std::string::npos) return make_error("chart path contains a quote");
    const std::string command = "/usr/bin/python3 -c \"$PROXYGI_CHART_SCRIPT\" '" + temporary.string() + "'";
    if (setenv("PROXYGI_CHART_SCRIPT", script.c_str(), 1) != 0) return make_error("setenv failed");
    std::FILE* pipe = popen(command.c_str(), "w");
    if (pipe == nullptr) return make_error("cannot start /usr/bin/python3");
    const bool sent = std::fwrite(text.data(), 1, text.size(), pipe) == text.size();
    const int status = pclose(pipe);
    if (!sent || status != 0) return make_error("matplotlib chart script failed");
    return {};
  });
}

}  // namespace proxygi::app
