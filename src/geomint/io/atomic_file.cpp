#include "geomint/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace geomint {

namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, std::string_view content) {
  const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot write " + path.string() + ": " + std::strerror(errno));
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.c_str());
      throw OutputError("cannot write " + path.string() + ": " + why);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw OutputError("cannot write " + path.string() + ": " + why);
  }
}

OutputDir::OutputDir(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) {
    throw OutputError("--out " + dir_.string() + ": cannot create the directory (" +
                      (ec ? ec.message() : std::string("not a directory")) + "); give a writable directory");
  }
  // Probe: create and remove a file, so a read-only directory fails now, not after the run.
  const fs::path probe = dir_ / (".write-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw OutputError("--out " + dir_.string() + ": directory is not writable (" + std::strerror(errno) +
                      "); give a writable directory");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

void OutputDir::write(const std::string& name, std::string_view content) {
  write_file_atomic(dir_ / name, content);
  if (std::find(written_.begin(), written_.end(), name) == written_.end()) written_.push_back(name);
}

}  // namespace geomint
