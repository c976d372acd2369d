#include "base/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "settings/limits.h"

namespace proxygi {
namespace {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  return path.string() + ".tmp-" + std::to_string(::getpid());
}

// Messages name the user's path, never the temporary: a person cannot find or fix a
// "<name>.tmp-<pid>" file that no longer exists.
Error system_error(const std::filesystem::path& path, const char* what) {
  return make_error(path.string() + ": cannot " + what + ": " + std::strerror(errno));
}

// A writer's own message (a library that opened the temporary) with the temporary's name
// replaced by the user's path.
Error naming_user_path(const Error& error, const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::string message = error.message;
  const std::string from = temporary.string(), to = path.string();
  for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
    message.replace(at, from.size(), to);
  const std::string name = temporary.filename().string();  // a bare file name, as some libraries print
  for (std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at + to.size()))
    message.replace(at, name.size(), to);
  return make_error(std::move(message));
}

}  // namespace

Status write_via_temporary(const std::filesystem::path& path,
                           const std::function<Status(const std::filesystem::path&)>& write) {
  const std::filesystem::path temporary = temporary_path_for(path);
  Status written = write(temporary);
  if (!written) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return naming_user_path(written.error(), temporary, path);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    Error error = system_error(path, "replace it (rename)");
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return error;
  }
  return {};
}

Status write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  return write_via_temporary(path, [&](const std::filesystem::path& temporary) -> Status {
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return system_error(path, "create it in its folder");
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        Error error = system_error(path, "write");
        ::close(fd);
        return error;
      }
      done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) {
      Error error = system_error(path, "flush (fsync)");
      ::close(fd);
      return error;
    }
    if (::close(fd) != 0) return system_error(path, "close");
    return {};
  });
}

Status write_file_atomically(const std::filesystem::path& path, std::string_view text) {
  return write_file_atomically(
      path, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

Result<std::vector<std::uint8_t>> read_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
  std::error_code code;
  const auto status = std::filesystem::status(path, code);
  if (code || !std::filesystem::exists(status)) return make_error(path.string() + ": no such file");
  if (!std::filesystem::is_regular_file(status)) return make_error(path.string() + ": not a regular file");
  const std::uint64_t size = std::filesystem::file_size(path, code);
  if (code) return make_error(path.string() + ": cannot read size: " + code.message());
  if (size > max_bytes)
    return make_error(path.string() + ": file is " + settings::readable_bytes(size) + ", more than the limit of " +
                      settings::readable_bytes(max_bytes) + " (not read)");
  std::vector<std::uint8_t> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    return make_error(path.string() + ": read failed");
  return bytes;
}

}  // namespace proxygi
