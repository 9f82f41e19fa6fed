#include "render/movie_encoder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "render/external_program.hpp"

extern char** environ;

namespace rodsort::render {
namespace {

/// Cairo's RGB24 pixel is a native-endian 32-bit word 0x00RRGGBB: its bytes in memory, as ffmpeg
/// names them.
constexpr const char* kRawPixelFormat =
    std::endian::native == std::endian::little ? "bgr0" : "0rgb";

int wait_for(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string read_tail(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return last_lines(text.str(), 10);
}

}  // namespace

MovieEncoder::MovieEncoder(const std::filesystem::path& ffmpeg, const std::filesystem::path& movie,
                           int width, int height, double fps, std::filesystem::path log)
    : movie_(movie), log_(std::move(log)), width_(width), height_(height) {
  char size[32];
  std::snprintf(size, sizeof size, "%dx%d", width, height);
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  const std::vector<std::string> arguments = {ffmpeg.string(),
                                              "-nostdin",
                                              "-y",
                                              "-loglevel",
                                              "error",
                                              "-f",
                                              "rawvideo",
                                              "-pix_fmt",
                                              kRawPixelFormat,
                                              "-video_size",
                                              size,
                                              "-framerate",
                                              rate,
                                              "-i",
                                              "pipe:0",
                                              "-pix_fmt",
                                              "yuv420p",
                                              "-movflags",
                                              "+faststart",
                                              movie.string()};

  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
    throw std::runtime_error("cannot start ffmpeg: socketpair: " +
                             std::string(std::strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sockets[1], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const int spawned =
      posix_spawn(&child_, arguments[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(sockets[1]);
  if (spawned != 0) {
    ::close(sockets[0]);
    child_ = -1;
    throw std::runtime_error("cannot start " + ffmpeg.string() + ": " + std::strerror(spawned));
  }
  socket_ = sockets[0];
}

MovieEncoder::~MovieEncoder() {
  if (socket_ >= 0) ::close(socket_);
  if (child_ > 0) {
    ::kill(child_, SIGTERM);
    wait_for(child_);
    std::error_code ignored;
    std::filesystem::remove(movie_, ignored);
  }
}

void MovieEncoder::add(cairo_surface_t* frame) {
  cairo_surface_flush(frame);
  const unsigned char* data = cairo_image_surface_get_data(frame);
  const int stride = cairo_image_surface_get_stride(frame);
  const std::size_t row_bytes = 4 * static_cast<std::size_t>(width_);
  for (int y = 0; y < height_; ++y) {
    const unsigned char* row = data + static_cast<std::ptrdiff_t>(y) * stride;
    std::size_t sent = 0;
    while (sent < row_bytes) {
      const ssize_t count = ::send(socket_, row + sent, row_bytes - sent, MSG_NOSIGNAL);
      if (count < 0 && errno == EINTR) continue;
      if (count <= 0) fail("ffmpeg stopped reading frames");
      sent += static_cast<std::size_t>(count);
    }
  }
  ++frames_;
}

void MovieEncoder::finish() {
  ::close(socket_);
  socket_ = -1;
  const int status = wait_for(child_);
  child_ = -1;
  if (status != 0) fail("ffmpeg failed (exit status " + std::to_string(status) + ")");
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
}

void MovieEncoder::fail(const std::string& what) {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  if (child_ > 0) {
    wait_for(child_);
    child_ = -1;
  }
  std::error_code ignored;
  std::filesystem::remove(movie_, ignored);
  throw std::runtime_error(what + " making " + movie_.string() + "; its messages, in " +
                           log_.string() + ":\n" + read_tail(log_));
}

}  // namespace rodsort::render
