// OpenEXR compression choices of a streamed skydome (exr_compression.h).
#include "api/skydome/exr_compression.h"

namespace clearsky::api {

Imf::Compression openexr_compression(ExrCompression compression) {
  switch (compression) {
    case ExrCompression::zip:
      return Imf::ZIP_COMPRESSION;
    case ExrCompression::piz:
      return Imf::PIZ_COMPRESSION;
    case ExrCompression::none:
      break;
  }
  return Imf::NO_COMPRESSION;
}

int lines_per_block(ExrCompression compression) {
  switch (compression) {
    case ExrCompression::zip:
      return 16;
    case ExrCompression::piz:
      return 32;
    case ExrCompression::none:
      break;
  }
  return 1;
}

std::size_t compressor_bytes(ExrCompression compression, std::size_t line_bytes) {
  const std::size_t block = static_cast<std::size_t>(lines_per_block(compression)) * line_bytes;
  switch (compression) {
    case ExrCompression::zip:
      // The block, its reordered copy and the compressed output (at most the block plus
      // zlib's bound), and deflate's window and hash tables (about 256 KiB at the defaults).
      return 3 * block + (std::size_t{512} << 10);
    case ExrCompression::piz:
      // The block, the 16-bit wavelet buffer, the output, the 8 KiB bitmap and the Huffman
      // encoder's tables (65,537 frequencies of 8 bytes and their heap).
      return 3 * block + (std::size_t{1} << 20);
    case ExrCompression::none:
      break;
  }
  return block;
}

std::string compression_name(ExrCompression compression) {
  switch (compression) {
    case ExrCompression::zip:
      return "zip";
    case ExrCompression::piz:
      return "piz";
    case ExrCompression::none:
      break;
  }
  return "none";
}

}  // namespace clearsky::api
