// batch_radiance: one POST /v1/radiance for a ring of views around the sky, printed as a table
// of spectral radiance, W/(m2.sr.nm), one row per wavelength and one column per view.
//
//   batch_radiance [URL] [MODEL] [SUN_ZENITH_DEG] [SUN_AZIMUTH_DEG] [VIEW_ZENITH_DEG]
//   batch_radiance http://127.0.0.1:8080 preetham 40 135 60
#include <clearsky/client/client.h>

#include <cstdio>
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

  clearsky::client::RadianceBatchRequest request;
  request.model = argument(2, "preetham");
  request.sun =
      clearsky::client::SunAngles{std::stod(argument(3, "40")), std::stod(argument(4, "135"))};
  const double view_zenith_deg = std::stod(argument(5, "60"));
  for (double azimuth_deg = 0; azimuth_deg < 360; azimuth_deg += 45)
    request.views.push_back({view_zenith_deg, azimuth_deg});
  try {
    const clearsky::client::RadianceResult result = client.radiance(request);
    std::printf("%s %s, sun %.2f/%.2f deg, %s\n", result.model.c_str(),
                result.model_version.c_str(), result.sun.zenith_deg, result.sun.azimuth_deg,
                result.unit.c_str());
    std::printf("%10s", "nm");
    for (const auto& sample : result.samples)
      std::printf(" %5.1f/%-5.1f", sample.view.zenith_deg, sample.view.azimuth_deg);
    std::printf("\n");
    for (std::size_t w = 0; w < result.wavelengths_nm.size(); ++w) {
      std::printf("%10.3f", result.wavelengths_nm[w]);
      for (const auto& sample : result.samples)
        std::printf(" %11.5f", sample.radiance_w_m2_sr_nm[w]);
      std::printf("\n");
    }
  } catch (const clearsky::client::Error& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
