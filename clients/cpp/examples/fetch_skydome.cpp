// fetch_skydome: what a renderer does to light a scene with a clearsky sky. It asks for a
// latitude-longitude OpenEXR environment map (linear sRGB, docs/http-api.md "RGB") and streams
// it to a file, never holding the image in memory.
//
//   fetch_skydome [URL] [MODEL] [SUN_ZENITH_DEG] [SUN_AZIMUTH_DEG] [WIDTH_PX] [FILE]
//   fetch_skydome http://127.0.0.1:8080 preetham 40 135 1024 sky.exr
#include <clearsky/client/client.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  const auto argument = [&](int i, const char* fallback) {
    return std::string(argc > i ? argv[i] : fallback);
  };
  clearsky::client::ClientOptions options;
  options.base_url = argument(1, "http://127.0.0.1:8080");
  const clearsky::client::Client client(options);

  clearsky::client::SkydomeRequest request;
  request.model = argument(2, "preetham");
  request.sun =
      clearsky::client::SunAngles{std::stod(argument(3, "40")), std::stod(argument(4, "135"))};
  request.projection = "latlong";
  request.size_px = std::stoi(argument(5, "1024"));
  request.channels = "rgb";
  const std::string file = argument(6, "sky.exr");
  try {
    const auto download = client.skydome_to_file(request, file);
    std::cout << file << ": " << download.bytes << " bytes (" << download.content_type << ")\n";
  } catch (const clearsky::client::Error& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
