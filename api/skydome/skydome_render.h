// GET /v1/skydome: an OpenEXR image of the sky computed band by band in parallel and streamed
// as it is computed, with memory bounded by one band (at most 16 rows and, when more than one
// row, about 2 MiB of float samples; independent of the image height).
//
// | parameter  | values                         | default  | meaning |
// |------------|--------------------------------|----------|-----------------------------------------|
// | projection | fisheye, latlong, cubemap      | fisheye  | skydome_projection.h | | size       |
// 8 .. max_skydome_size (even)   | 512      | width (and fisheye height; cube face)   | | channels
// | rgb, luminance, spectral       | rgb      | R,G,B linear sRGB; Y in cd/m2; or one channel per
// wavelength | | pixel_type | half, float                    | half for rgb, float otherwise | | |
// method     | spectral, three (rgb only)     | spectral | as GET /v1/rgb | | wavelengths| list or
// start:stop:step (spectral only) | the model's grid |                      | plus the sky
// parameters of sky_request.h (model, sun or place and time, altitude, atmosphere). Spectral images
// follow Fichet, Pacanowski and Wilkie 2021, "An OpenEXR Layout for Spectral Images" (JCGT 10(3)):
// emissive channels "S0.<nm with comma decimals>nm" (e.g. S0.550,000000nm) in W/(m2.sr.nm),
// attributes spectralLayoutVersion = "1.0" and emissiveUnits = "W.m^-2.sr^-1". The renderer
// options sun, ground, units and compression are the table of api/skydome/skydome_options.h:
// the solar disc (sun_disc.h), the ground below the horizon (skydome_ground.h), photometric RGB
// and OpenEXR compression (exr_compression.h; uncompressed scan lines by default, whose offset
// table is known before the pixels). Directions the model does not answer (outside the fisheye
// circle, below the horizon without a ground) are 0 with A = 0. RGB images have no negative
// component: out of gamut colours are clipped (api/colour/srgb_gamut.h), as the attribute
// clearskyGamutMapping says. pixel_type defaults to half for radiometric RGB without the sun's
// disc, float otherwise (half cannot hold the disc or photometric values: 400).
// format=png (with exposure and tone_map, api/colour/display_tone_mapping.h) sends instead an
// 8-bit RGBA sRGB PNG of the rgb image written row by row by libpng (api/skydome/png_stream.h),
// alpha 0 where the model did not answer; same projections, sizes and bands.
// prepare_skydome() checks everything (errors are ApiError, before any byte is sent).
#pragma once

#include <functional>
#include <memory>

#include "api/http/api_types.h"
#include "api/skydome/skydome_projection.h"

namespace clearsky::api {

// How SkydomeRender::write() computes its pixels. fast: the rows of a latlong map that lie
// wholly below the horizon (half the image) are filled with the ground's pixel, computed once
// per image, instead of a direction and a colour per pixel; the other pixels as per_pixel.
// per_pixel: every pixel's direction and colour computed on its own, the computation of earlier
// releases, kept as the slow reference that tests (bit for bit) and the benchmark compare the
// fast path with (docs/performance.md "RGB skydome").
enum class SkydomePixelPath { fast, per_pixel };

class SkydomeRender {
 public:
  using Sink = std::function<bool(const char* data, std::size_t size)>;
  struct Settings;

  explicit SkydomeRender(std::shared_ptr<const Settings> settings)
      : settings_(std::move(settings)) {}
  // Computes and writes the whole file to sink; false when the sink refused data (client
  // gone), in which case the computation stops. Throws on internal errors only.
  // unanswered_pixels: directions the model should answer but gave no value for (a status
  // other than ok or below-horizon), written as 0.
  bool write(const Sink& sink, unsigned threads = 0, std::size_t* unanswered_pixels = nullptr,
             SkydomePixelPath path = SkydomePixelPath::fast) const;
  const std::string& model_id() const;
  // Clearsky-Quality, Clearsky-Served-Quality, Clearsky-Quality-Detail (api/request/quality.h).
  void add_quality_headers(std::vector<std::pair<std::string, std::string>>& headers) const;
  // Clearsky-Fit when the request named a fit (api/request/sky_fit.h).
  void add_fit_headers(std::vector<std::pair<std::string, std::string>>& headers) const;
  int width() const;
  int height() const;
  // "image/x-exr" and "sky.exr", or "image/png" and "sky.png" (format=png).
  const char* content_type() const;
  const char* file_name() const;
  // The bytes write() holds for the whole answer, however slowly the sink takes them: its band
  // of rows (float, plus half when the pixels are half), one scan line in OpenEXR's line buffer
  // and one being sent (a chunk the HTTP layer copies). What the server's answer memory budget reserves (api/http/answer_memory_budget.h).
  std::size_t band_bytes() const;

 private:
  std::shared_ptr<const Settings> settings_;
};

SkydomeRender prepare_skydome(const ApiContext& context, const ApiRequest& request);

// "S0.550,000000nm" for 550 nm (Fichet et al. 2021).
std::string spectral_channel_name(double wavelength_nm);

}  // namespace clearsky::api
