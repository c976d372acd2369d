#include "base/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

namespace proxygi {
namespace {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  return path.string() + ".tmp-" + std::to_string(::getpid());
}

Error system_error(const std::filesystem::path& path, const char* call) {
  return make_error(path.string() + ": " + call + " failed: " + std::strerror(errno));
}

}  // namespace

Status write_via_temporary(const std::filesystem::path& path,
                           const std::function<Status(const std::filesystem::path&)>& write) {
  const std::filesystem::path temporary = temporary_path_for(path);
  Status written = write(temporary);
  if (!written) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return written;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    Error error = system_error(path, "rename");
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return error;
  }
  return {};
}

Status write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  return write_via_temporary(path, [&](const std::filesystem::path& temporary) -> Status {
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return system_error(temporary, "open");
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        Error error = system_error(temporary, "write");
        ::close(fd);
        return error;
      }
      done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) return system_error(temporary, "fsync/close");
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
    return make_error(path.string() + ": file is " + std::to_string(size) + " bytes, limit is " +
                      std::to_string(max_bytes));
  std::vector<std::uint8_t> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    return make_error(path.string() + ": read failed");
  return bytes;
}

}  // namespace proxygi
