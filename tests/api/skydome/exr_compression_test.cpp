// Compressed skydomes (api/skydome/exr_compression.h): written through SkydomeRender without a
// socket, the zip and piz files pass the stream's own check of the offset table OpenEXR writes on
// close (write() throws otherwise) and decode with OpenEXR, which rebuilds their zero offset
// table, to the pixels of the uncompressed file.
#include "api/skydome/exr_compression.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <gtest/gtest.h>

#include "api/skydome/skydome_render.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

std::string render(const std::string& compression) {
  const clearsky::testing::SynchronousProvider provider(clearsky::testing::test_factories());
  const ApiContext context{provider, Limits{}};
  ApiRequest request;
  request.path = request.route = "/v1/skydome";
  request.query = {{"model", "testsky"},        {"sun_zenith", "50"}, {"sun_azimuth", "100"},
                   {"projection", "latlong"},   {"size", "80"},       {"sun", "disc"},
                   {"compression", compression}};
  const SkydomeRender skydome = prepare_skydome(context, request);
  std::string bytes;
  EXPECT_TRUE(skydome.write([&](const char* data, std::size_t size) {
    bytes.append(data, size);
    return true;
  }));
  return bytes;
}

std::vector<float> channel(const std::string& bytes, const char* name) {
  Imf::StdISStream stream;
  stream.str(bytes);
  Imf::InputFile file(stream);
  const auto dw = file.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<float> values(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  Imf::FrameBuffer frame;
  frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                sizeof(float) * static_cast<std::size_t>(w)));
  file.setFrameBuffer(frame);
  file.readPixels(dw.min.y, dw.max.y);
  return values;
}

TEST(ExrCompression, ZipAndPizDecodeToTheUncompressedPixels) {
  const std::string plain = render("none");
  for (const char* compression : {"zip", "piz"}) {
    const std::string packed = render(compression);
    EXPECT_LT(packed.size(), plain.size()) << compression;
    for (const char* name : {"R", "G", "B", "A"})
      EXPECT_EQ(channel(packed, name), channel(plain, name)) << compression << " " << name;
  }
}

TEST(ExrCompression, BlocksAndBuffers) {
  EXPECT_EQ(openexr_compression(ExrCompression::none), Imf::NO_COMPRESSION);
  EXPECT_EQ(openexr_compression(ExrCompression::zip), Imf::ZIP_COMPRESSION);
  EXPECT_EQ(openexr_compression(ExrCompression::piz), Imf::PIZ_COMPRESSION);
  EXPECT_EQ(lines_per_block(ExrCompression::none), 1);
  // OpenEXR's block heights (the OpenEXR file layout: ZIP 16 scan lines, PIZ 32).
  EXPECT_EQ(lines_per_block(ExrCompression::zip), 16);
  EXPECT_EQ(lines_per_block(ExrCompression::piz), 32);
  for (ExrCompression c : {ExrCompression::zip, ExrCompression::piz})
    EXPECT_GT(compressor_bytes(c, 1000), 3u * static_cast<std::size_t>(lines_per_block(c)) * 1000);
}

}  // namespace
}  // namespace clearsky::api
