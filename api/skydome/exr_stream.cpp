// Streaming of an uncompressed scan-line EXR.
#include "api/skydome/exr_stream.h"

#include <cstring>

namespace clearsky::api {

std::vector<std::uint64_t> uncompressed_chunk_offsets(std::uint64_t table_end, int lines,
                                                      std::uint64_t line_bytes) {
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(lines));
  for (int i = 0; i < lines; ++i)
    offsets[static_cast<std::size_t>(i)] =
        table_end + static_cast<std::uint64_t>(i) * (8 + line_bytes);
  return offsets;
}

void ExrStream::send(const char* data, std::size_t size) {
  if (aborted_) throw StreamAborted();
  if (!sink_(data, size)) {
    aborted_ = true;
    throw StreamAborted();
  }
  sent_ += size;
}

void ExrStream::write(const char c[], int n) {
  const auto size = static_cast<std::size_t>(n);
  if (!started_) {
    // The constructor writes sequentially from 0.
    if (position_ != held_.size()) throw std::logic_error("ExrStream: seek before start()");
    held_.append(c, size);
    position_ += size;
    return;
  }
  if (position_ < sent_ && zero_table_) {
    // The OutputFile writing its offset table at close: kept to be checked.
    if (position_ < table_start_ || position_ + size > table_start_ + table_.size()) {
      table_matches_ = false;
    } else {
      closing_table_.replace(position_ - table_start_, size, c, size);
    }
    position_ += size;
    return;
  }
  if (position_ < sent_) {
    // The OutputFile rewriting its offset table at close: it must be what was sent.
    if (position_ < table_start_ || position_ + size > table_start_ + table_.size() ||
        std::memcmp(table_.data() + (position_ - table_start_), c, size) != 0) {
      table_matches_ = false;
    }
    position_ += size;
    return;
  }
  if (position_ != sent_) throw std::logic_error("ExrStream: gap in the stream");
  send(c, size);
  position_ += size;
}

void ExrStream::start_with_zero_table(std::size_t chunk_count) {
  const std::size_t table_bytes = 8 * chunk_count;
  if (held_.size() < table_bytes) throw std::logic_error("ExrStream: no offset table written");
  table_start_ = held_.size() - table_bytes;
  table_.assign(table_bytes, '\0');
  closing_table_.assign(table_bytes, '\0');
  std::memcpy(held_.data() + table_start_, table_.data(), table_bytes);
  zero_table_ = true;
  started_ = true;
  send(held_.data(), held_.size());
  held_.clear();
  held_.shrink_to_fit();
}

bool ExrStream::matches_sent_table() const {
  if (!table_matches_) return false;
  if (!zero_table_) return true;
  std::uint64_t previous = table_start_ + table_.size() - 1;
  for (std::size_t i = 0; i + 8 <= closing_table_.size(); i += 8) {
    std::uint64_t offset = 0;
    for (int b = 7; b >= 0; --b)
      offset = (offset << 8) |
               static_cast<unsigned char>(closing_table_[i + static_cast<std::size_t>(b)]);
    if (offset <= previous || offset >= sent_) return false;
    previous = offset;
  }
  return true;
}

void ExrStream::start(const std::vector<std::uint64_t>& chunk_offsets) {
  const std::size_t table_bytes = 8 * chunk_offsets.size();
  if (held_.size() < table_bytes) throw std::logic_error("ExrStream: no offset table written");
  table_start_ = held_.size() - table_bytes;
  table_.clear();
  for (std::uint64_t offset : chunk_offsets) {
    for (int b = 0; b < 8; ++b) table_.push_back(static_cast<char>((offset >> (8 * b)) & 0xff));
  }
  std::memcpy(held_.data() + table_start_, table_.data(), table_bytes);
  started_ = true;
  send(held_.data(), held_.size());
  held_.clear();
  held_.shrink_to_fit();
}

}  // namespace clearsky::api
