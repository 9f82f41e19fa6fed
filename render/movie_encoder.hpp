#pragma once
// Movies: frames drawn into one image surface are streamed, raw, to an ffmpeg process that
// encodes them as they come (H.264 where ffmpeg has it, yuv420p so that every player opens it).
// Streaming skips the PNG encoding of each frame, which costs more than drawing it, and lets
// ffmpeg encode on other cores while the next frame is drawn.
//
// The frames go through a socket pair rather than a pipe, so that writing to an ffmpeg that has
// died is an error returned (MSG_NOSIGNAL), not a SIGPIPE that kills rodsort.

#include <cairo.h>
#include <sys/types.h>

#include <filesystem>
#include <string>

namespace rodsort::render {

class MovieEncoder {
 public:
  /// Starts `ffmpeg` writing `movie` from frames of width x height pixels (both even), `fps`
  /// frames per second. Its messages go to `log`, removed when the movie is made. Throws
  /// std::runtime_error when it cannot start.
  MovieEncoder(const std::filesystem::path& ffmpeg, const std::filesystem::path& movie, int width,
               int height, double fps, std::filesystem::path log);
  /// Stops ffmpeg if finish() was not reached (an error elsewhere): no half movie is left.
  ~MovieEncoder();
  MovieEncoder(const MovieEncoder&) = delete;
  MovieEncoder& operator=(const MovieEncoder&) = delete;

  /// Sends one frame: an RGB24 image surface of the encoder's size. Throws std::runtime_error with
  /// ffmpeg's last messages when it has stopped.
  void add(cairo_surface_t* frame);
  /// Ends the stream and waits for ffmpeg. Throws std::runtime_error with its last messages when
  /// it failed.
  void finish();

  int frames() const { return frames_; }

 private:
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path movie_;
  std::filesystem::path log_;
  int width_, height_;
  int socket_ = -1;  ///< our end of the stream to ffmpeg's standard input
  pid_t child_ = -1;
  int frames_ = 0;
};

}  // namespace rodsort::render
