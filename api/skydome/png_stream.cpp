// libpng writing row by row to a sink (png_stream.h).
#include "api/skydome/png_stream.h"

#include <png.h>

#include <csetjmp>
#include <stdexcept>

namespace clearsky::api {

namespace {

struct PngContext {
  PngStream::Sink* sink;
  bool* aborted;
  std::string* error;
};

// libpng's error callback: keeps the message and returns to the setjmp of the call in progress.
[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
  if (context != nullptr && context->error->empty()) *context->error = message;
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// libpng's write callback: the sink, whose refusal (or exception) ends the image.
void write_data(png_structp png, png_bytep data, std::size_t size) {
  auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
  bool sent = false;
  try {
    sent = (*context->sink)(reinterpret_cast<const char*>(data), size);
  } catch (...) {
    sent = false;
  }
  if (!sent) {
    *context->aborted = true;
    png_error(png, "the client stopped reading");
  }
}

void flush_data(png_structp) {}

// The calls into libpng, each under its own setjmp (no object with a destructor in these frames).
bool png_begin(png_structp png, png_infop info, int width, int height, png_textp text,
               int text_count) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (text_count > 0) png_set_text(png, info, text, text_count);
  png_write_info(png, info);
  return true;
}

bool png_row(png_structp png, const std::uint8_t* row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_write_row(png, row);
  return true;
}

bool png_flush(png_structp png) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_write_flush(png);
  return true;
}

bool png_end(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_write_end(png, info);
  return true;
}

}  // namespace

PngStream::PngStream(Sink sink, int width, int height,
                     const std::vector<std::pair<std::string, std::string>>& text)
    : sink_(std::move(sink)) {
  auto* context = new PngContext{&sink_, &aborted_, &error_};
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, context, on_png_error, on_png_warning);
  if (png == nullptr) {
    delete context;
    throw std::runtime_error("libpng: cannot create a write structure");
  }
  png_ = png;
  png_infop info = png_create_info_struct(png);
  info_ = info;
  if (info == nullptr) {
    release();
    throw std::runtime_error("libpng: cannot create an info structure");
  }
  png_set_write_fn(png, context, write_data, flush_data);
  std::vector<png_text> chunks(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
    chunks[i].key = const_cast<char*>(text[i].first.c_str());
    chunks[i].text = const_cast<char*>(text[i].second.c_str());
    chunks[i].text_length = text[i].second.size();
  }
  if (!png_begin(png, info, width, height, chunks.data(), static_cast<int>(chunks.size()))) {
    failed_ = true;
    if (!aborted_) {
      const std::string error = error_;
      release();
      throw std::runtime_error("libpng: " + error);
    }
  }
}

PngStream::~PngStream() { release(); }

void PngStream::release() {
  auto png = static_cast<png_structp>(png_);
  auto info = static_cast<png_infop>(info_);
  if (png == nullptr) return;
  auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
  png_destroy_write_struct(&png, info != nullptr ? &info : nullptr);
  delete context;
  png_ = nullptr;
  info_ = nullptr;
}

bool PngStream::write_row(const std::uint8_t* rgba) {
  if (failed_) return false;
  if (!png_row(static_cast<png_structp>(png_), rgba)) {
    failed_ = true;
    if (!aborted_) throw std::runtime_error("libpng: " + error_);
    return false;
  }
  return true;
}

bool PngStream::flush() {
  if (failed_) return false;
  if (!png_flush(static_cast<png_structp>(png_))) {
    failed_ = true;
    if (!aborted_) throw std::runtime_error("libpng: " + error_);
    return false;
  }
  return true;
}

bool PngStream::finish() {
  if (failed_) return false;
  if (!png_end(static_cast<png_structp>(png_), static_cast<png_infop>(info_))) {
    failed_ = true;
    if (!aborted_) throw std::runtime_error("libpng: " + error_);
    return false;
  }
  return true;
}

std::size_t PngStream::state_bytes(int width) {
  // zlib: (1 << 17) + (1 << 17) for windowBits 15 and memLevel 8; libpng: the current and
  // previous rows and one filtered row per filter type tried (at most 5), 4 bytes a pixel.
  return (std::size_t{1} << 18) + 7 * (static_cast<std::size_t>(width) * 4 + 1);
}

}  // namespace clearsky::api
