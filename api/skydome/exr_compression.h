// OpenEXR compression of a streamed skydome (GET /v1/skydome compression=, docs/http-api.md):
// what each choice is in OpenEXR, how many scan lines it packs into a block, and the memory
// OpenEXR holds while it compresses one.
//
// An uncompressed file's block sizes are known before any pixel, so its offset table is
// computed and sent first (exr_stream.h). A compressed block's size is known only once it is
// compressed, and the table comes before every block, so a compressed skydome is sent with a
// table of zeros and each block as soon as OpenEXR has compressed it (the memory stays one
// block). A zero offset is OpenEXR's mark of a file whose table was never written (an
// interrupted write): OpenEXR's readers (ScanLineInputFile, and OpenEXRCore's chunk table)
// then rebuild the table by reading the blocks' headers in order, which is what Blender, and
// the OpenEXR-based importers of Unreal and Unity, do; three.js's EXRLoader reads the blocks in
// order and never reads the table. `exrheader` calls such a file "incomplete" (it reads the
// table only); `exrstdattr in.exr out.exr` rewrites it with its table.
// Pure functions; thread-safe.
#pragma once

#include <OpenEXR/ImfCompression.h>

#include <cstddef>
#include <string>

#include "api/skydome/skydome_options.h"

namespace clearsky::api {

Imf::Compression openexr_compression(ExrCompression compression);
// OpenEXR's scan lines per block: 1 (none), 16 (zip), 32 (piz).
int lines_per_block(ExrCompression compression);
// Bytes OpenEXR holds while writing one block of line_bytes-long scan lines, besides the
// caller's frame buffer: the block's pixels, the compressor's buffers and, for zip, zlib's
// deflate state; for piz, its wavelet buffer and Huffman tables (ImfZipCompressor.cpp,
// ImfPizCompressor.cpp).
std::size_t compressor_bytes(ExrCompression compression, std::size_t line_bytes);
std::string compression_name(ExrCompression compression);

}  // namespace clearsky::api
