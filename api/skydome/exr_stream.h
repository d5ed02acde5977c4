// An OpenEXR output stream that sends the file as it is written, for responses that cannot
// seek. A scan-line EXR starts with a table of chunk offsets that Imf::OutputFile fills in
// only when it closes (by seeking back). Without compression every chunk's size is known in
// advance, so the table can be computed before any pixel: this stream holds back what the
// OutputFile constructor writes (header and the zeroed table), and start() replaces the table
// with the computed offsets and sends it; pixels then pass straight through. The table the
// OutputFile writes when it closes is compared with what was sent (matches_sent_table()).
// A compressed file's table cannot be known before its pixels (exr_compression.h):
// start_with_zero_table() sends the table as zeros, and the table the OutputFile writes when it
// closes is checked to point at blocks that were sent, in order (matches_sent_table()).
// A sink returning false (client gone) makes every later write throw StreamAborted.
// Not thread-safe: one writer.
#pragma once

#include <OpenEXR/ImfIO.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace clearsky::api {

class StreamAborted : public std::runtime_error {
 public:
  StreamAborted() : std::runtime_error("the client stopped reading") {}
};

class ExrStream final : public Imf::OStream {
 public:
  using Sink = std::function<bool(const char* data, std::size_t size)>;
  explicit ExrStream(Sink sink) : Imf::OStream("http response"), sink_(std::move(sink)) {}

  void write(const char c[], int n) override;
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = position; }

  // Call after the OutputFile constructor: the last 8 * chunk_offsets.size() bytes written are
  // the offset table, replaced by chunk_offsets; sends everything held back.
  void start(const std::vector<std::uint64_t>& chunk_offsets);
  // Call after the OutputFile constructor: the last 8 * chunk_count bytes written are the offset
  // table, sent as zeros (OpenEXR's readers rebuild it), with everything held back.
  void start_with_zero_table(std::size_t chunk_count);
  // Uncompressed: the table OpenEXR wrote on close is the one sent. Zero table: it was written
  // whole, its offsets increase and each lies within what was sent.
  bool matches_sent_table() const;
  bool aborted() const { return aborted_; }
  std::uint64_t bytes_sent() const { return sent_; }

 private:
  void send(const char* data, std::size_t size);

  Sink sink_;
  std::string held_;
  bool started_ = false;
  bool aborted_ = false;
  bool table_matches_ = true;
  bool zero_table_ = false;
  std::string closing_table_;  // with a zero table: the table OpenEXR wrote when it closed
  std::uint64_t position_ = 0;
  std::uint64_t sent_ = 0;
  std::uint64_t table_start_ = 0;
  std::string table_;
};

// Offsets of the chunks of an uncompressed scan-line file: one scan line per chunk, each
// 4 bytes of y, 4 bytes of size and line_bytes of pixels, after the offset table.
std::vector<std::uint64_t> uncompressed_chunk_offsets(std::uint64_t table_end, int lines,
                                                      std::uint64_t line_bytes);

}  // namespace clearsky::api
