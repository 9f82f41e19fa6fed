#include "runner/append_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rodsort::runner {
namespace {

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path) {
  throw std::runtime_error(what + " " + path.string() + ": " + std::strerror(errno));
}

}  // namespace

AppendFile::AppendFile(std::filesystem::path path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) fail("cannot open", path_);
  struct stat status {};
  if (::fstat(fd_, &status) != 0) fail("cannot stat", path_);
  size_ = static_cast<std::uint64_t>(status.st_size);
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", path_);
    }
    written += static_cast<std::size_t>(n);
  }
  size_ += text.size();
}

void AppendFile::sync() {
  if (::fdatasync(fd_) != 0) fail("cannot flush", path_);
}

void AppendFile::truncate(std::uint64_t bytes) {
  if (bytes > size_) {
    throw std::runtime_error(path_.string() + " holds " + std::to_string(size_) +
                             " bytes, fewer than the " + std::to_string(bytes) +
                             " its checkpoint records");
  }
  if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0) fail("cannot truncate", path_);
  size_ = bytes;
}

}  // namespace rodsort::runner
