// An OpenEXR file received whole (a GET /v1/skydome answer) decoded with OpenEXR: every
// channel as float, and the string attributes of its header.
#pragma once

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <map>
#include <string>
#include <vector>

namespace clearsky::server::testing {

struct DecodedExr {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> channels;
  std::map<std::string, std::string> strings;
};

inline DecodedExr decode(const std::string& bytes) {
  Imf::StdISStream stream;
  stream.str(bytes);
  Imf::InputFile file(stream);
  DecodedExr out;
  const auto dw = file.header().dataWindow();
  out.width = dw.max.x - dw.min.x + 1;
  out.height = dw.max.y - dw.min.y + 1;
  Imf::FrameBuffer frame;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
    auto& data = out.channels[it.name()];
    data.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
    frame.insert(it.name(),
                 Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data.data()), sizeof(float),
                            sizeof(float) * static_cast<std::size_t>(out.width)));
  }
  for (auto it = file.header().begin(); it != file.header().end(); ++it) {
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
      out.strings[it.name()] = s->value();
  }
  file.setFrameBuffer(frame);
  file.readPixels(dw.min.y, dw.max.y);
  return out;
}

}  // namespace clearsky::server::testing
