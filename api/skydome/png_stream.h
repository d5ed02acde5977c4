// A PNG image written row by row with libpng (the PNG specification, ISO/IEC 15948:2004) to a
// sink, for the PNG skydome: 8-bit RGBA, non-interlaced, an sRGB chunk (rendering intent
// perceptual) and tEXt chunks. Each row goes through zlib as it comes, so the memory is libpng's
// and zlib's state, not the image. A sink returning false (client gone) ends the image: every
// later call returns false and writes nothing.
// libpng reports errors by longjmp (its manual, "Setjmp/longjmp issues"): each call into libpng
// is made from a function whose frame holds no object with a destructor, and the write callback
// catches every exception before it returns to libpng.
// Not thread-safe: one writer.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace clearsky::api {

class PngStream {
 public:
  using Sink = std::function<bool(const char* data, std::size_t size)>;

  // Writes the signature and the header chunks. Throws std::runtime_error if libpng fails for
  // another reason than the sink.
  PngStream(Sink sink, int width, int height,
            const std::vector<std::pair<std::string, std::string>>& text);
  ~PngStream();
  PngStream(const PngStream&) = delete;
  PngStream& operator=(const PngStream&) = delete;

  // One row of width x 4 bytes (R, G, B, A). False when the sink refused data.
  bool write_row(const std::uint8_t* rgba);
  // Sends what zlib holds of the rows written so far (a sync flush: a few bytes more, so that
  // the client sees each band as it is computed rather than every 8 KiB of compressed data).
  // False when the sink refused data.
  bool flush();
  // The end of the image (IEND), after the last row. False when the sink refused data.
  bool finish();
  bool aborted() const { return aborted_; }

  // The bytes libpng and zlib hold while writing (zlib's deflate state with the default window
  // and memory level, zconf.h: (1 << (windowBits + 2)) + (1 << (memLevel + 9)); libpng's rows).
  static std::size_t state_bytes(int width);

 private:
  void release();

  Sink sink_;
  void* png_ = nullptr;   // png_structp
  void* info_ = nullptr;  // png_infop
  bool aborted_ = false;
  bool failed_ = false;
  std::string error_;
};

}  // namespace clearsky::api
