// Skydome parsing, band-parallel evaluation and streamed EXR encoding.
#include "api/skydome/skydome_render.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdio>

#include "api/colour/display_tone_mapping.h"
#include "api/colour/srgb_gamut.h"
#include "api/colour/xyz_weights.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/skydome/exr_stream.h"
#include "api/skydome/png_stream.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/core/parallel.h"

namespace clearsky::api {

struct SkydomeRender::Settings {
  std::string model_id;
  ModelOnGrid m;
  std::shared_ptr<const SunState> sun_state;
  SunSpec sun;
  Viewpoint viewpoint;
  SkydomeProjection projection{Projection::fisheye, 8};
  std::string channels;
  std::string method;
  bool half = true;
  // format=png: 8-bit sRGB through display_tone_mapping.h, instead of the EXR.
  bool png = false;
  double exposure_ev100 = kDefaultExposureEv100;
  ToneCurve tone_curve = ToneCurve::aces;
  std::string projection_name;
  std::unique_ptr<XyzWeights> xyz;
};

namespace {

// A band is at most 16 rows, and fewer when its float samples would be above 2 MiB (wide images
// with many channels: a 4096-pixel spectral row of 41 channels is 672 kB, 3 rows a band), since
// a band is what a slowly read answer holds (docs/deployment.md "Memory"). Each row is computed in
// pieces of 256 pixels over the cores, so a band of a few wide rows keeps every core busy.
constexpr int kMaxBandRows = 16;
constexpr std::size_t kBandTargetBytes = std::size_t{2} << 20;
constexpr int kPiecePixels = 256;

// The image is streamed, its header sent before any pixel: it states the rule, since it cannot
// count the clipped pixels (GET/POST /v1/rgb flag each sample).
constexpr const char* kGamutMapping =
    "negative linear sRGB components clipped to 0 (out of gamut colours); other values as "
    "computed";

// R, G, B of a pixel, mapped into the sRGB gamut (api/colour/srgb_gamut.h).
void write_rgb(float* pixel, const LinearSrgb& colour) {
  const LinearSrgb c = clip_to_srgb_gamut(colour).rgb;
  pixel[0] = static_cast<float>(c.r);
  pixel[1] = static_cast<float>(c.g);
  pixel[2] = static_cast<float>(c.b);
}

const ThreeWavelengthRgb& three_wavelength_method() {
  static const ThreeWavelengthRgb method;
  return method;
}

// Channels of the image, alpha included (the order is write()'s).
std::size_t channel_count(const SkydomeRender::Settings& s) {
  if (s.channels == "rgb") return 4;
  if (s.channels == "luminance") return 2;
  return s.m.wavelengths_nm.size() + 1;
}

// Rows of a band (kBandTargetBytes).
int band_rows(const SkydomeRender::Settings& s) {
  const std::size_t row_bytes =
      static_cast<std::size_t>(s.projection.width()) * channel_count(s) * sizeof(float);
  return static_cast<int>(std::clamp<std::size_t>(kBandTargetBytes / row_bytes, 1,
                                                  static_cast<std::size_t>(kMaxBandRows)));
}

// Rows [y0, y0 + rows) of the image into band (rows x width pixels of channel_count(s) floats,
// channel-interleaved, the coverage A last), over the cores in pieces of kPiecePixels.
void compute_band(const SkydomeRender::Settings& s, int y0, int rows, float* band, unsigned threads,
                  std::atomic<int>& failed_pixels) {
  const int width = s.projection.width();
  const std::size_t n_channels = channel_count(s);
  const std::size_t alpha_channel = n_channels - 1;
  const SkyModel& model = *s.m.model;
  const ThreeWavelengthRgb& three = three_wavelength_method();
  const std::size_t pieces = static_cast<std::size_t>((width + kPiecePixels - 1) / kPiecePixels);
  parallel_for(
      static_cast<std::size_t>(rows) * pieces,
      [&](std::size_t task) {
        const std::size_t r = task / pieces;
        const int y = y0 + static_cast<int>(r);
        const int x_begin = static_cast<int>(task % pieces) * kPiecePixels;
        const int x_end = std::min(width, x_begin + kPiecePixels);
        std::vector<ViewDirection> views;
        std::vector<int> columns;
        views.reserve(static_cast<std::size_t>(x_end - x_begin));
        for (int x = x_begin; x < x_end; ++x) {
          SkyDirection d;
          if (s.projection.direction(x, y, d)) {
            views.push_back(d);
            columns.push_back(x);
          }
        }
        float* row = band + r * static_cast<std::size_t>(width) * n_channels;
        std::fill(row + static_cast<std::size_t>(x_begin) * n_channels,
                  row + static_cast<std::size_t>(x_end) * n_channels, 0.0f);
        if (views.empty()) return;
        SpectralBatch batch;
        model.sky_radiance(*s.sun_state, s.viewpoint, views, batch);
        for (std::size_t k = 0; k < views.size(); ++k) {
          if (batch.status[k] != SampleStatus::ok) {
            if (batch.status[k] != SampleStatus::view_below_horizon_unsupported) ++failed_pixels;
            continue;
          }
          const auto l = batch.spectrum(k);
          float* px = row + static_cast<std::size_t>(columns[k]) * n_channels;
          px[alpha_channel] = 1.0f;
          if (s.channels == "spectral") {
            for (std::size_t c = 0; c < alpha_channel; ++c)
              px[c] = static_cast<float>(l[s.m.indices[c]]);
          } else if (s.method == "three") {
            const LinearSrgb c = three.rgb(l[s.m.indices[2]], l[s.m.indices[1]], l[s.m.indices[0]]);
            if (s.channels == "rgb") {
              write_rgb(px, c);
            } else {
              px[0] = static_cast<float>(kMaxLuminousEfficacy * linear_srgb_to_xyz(c).y);
            }
          } else {
            const Xyz xyz = s.xyz->xyz(l);
            if (s.channels == "rgb") {
              write_rgb(px, xyz_to_linear_srgb(xyz));
            } else {
              px[0] = static_cast<float>(kMaxLuminousEfficacy * xyz.y);
            }
          }
        }
      },
      threads);
}

// The PNG form (format=png): each band tone-mapped (display_tone_mapping.h) into 8-bit RGBA rows,
// alpha 255 where the model answered and 0 where it did not, each row given to libpng as it is
// made and each band flushed to the client. False when the client stopped reading.
bool write_png(const SkydomeRender::Settings& s, const SkydomeRender::Sink& sink, unsigned threads,
               std::size_t* unanswered_pixels) {
  const int width = s.projection.width();
  const int height = s.projection.height();
  const DisplayToneMapping display(s.exposure_ev100, s.tone_curve);
  char exposure[32];
  std::snprintf(exposure, sizeof exposure, "%g", s.exposure_ev100);
  const std::vector<std::pair<std::string, std::string>> text = {
      {"Software", "clearsky GET /v1/skydome"},
      {"clearskyModel", s.model_id},
      {"clearskyProjection", s.projection_name},
      {"sunZenithDeg", std::to_string(s.sun.zenith_deg)},
      {"sunAzimuthDeg", std::to_string(s.sun.azimuth_deg)},
      {"clearskyExposureEV100", exposure},
      {"clearskyToneMap", s.tone_curve == ToneCurve::aces ? "aces" : "reinhard"},
      {"clearskyAlpha", "255 where the model answered, 0 where it did not"}};
  PngStream png(sink, width, height, text);
  if (png.aborted()) return false;
  const std::size_t n_channels = channel_count(s);
  const int rows_per_band = band_rows(s);
  std::vector<float> band(static_cast<std::size_t>(rows_per_band) *
                          static_cast<std::size_t>(width) * n_channels);
  std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 4);
  std::atomic<int> failed_pixels{0};
  for (int y0 = 0; y0 < height; y0 += rows_per_band) {
    const int rows = std::min(rows_per_band, height - y0);
    compute_band(s, y0, rows, band.data(), threads, failed_pixels);
    for (int r = 0; r < rows; ++r) {
      const float* in = band.data() + static_cast<std::size_t>(r) * width * n_channels;
      for (int x = 0; x < width; ++x) {
        const float* px = in + static_cast<std::size_t>(x) * n_channels;
        const auto rgb = display.display({px[0], px[1], px[2]});
        std::uint8_t* out = row.data() + static_cast<std::size_t>(x) * 4;
        out[0] = rgb[0];
        out[1] = rgb[1];
        out[2] = rgb[2];
        out[3] = px[3] > 0.0f ? 255 : 0;
      }
      if (!png.write_row(row.data())) return false;
    }
    if (!png.flush()) return false;
  }
  if (!png.finish()) return false;
  if (unanswered_pixels != nullptr)
    *unanswered_pixels = static_cast<std::size_t>(failed_pixels.load());
  return true;
}

}  // namespace

std::string spectral_channel_name(double wavelength_nm) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "S0.%.6fnm", wavelength_nm);
  std::string name = buffer;
  for (char& c : name) {
    if (c == '.' && &c != &name[2]) c = ',';
  }
  return name;
}

SkydomeRender prepare_skydome(const ApiContext& context, const ApiRequest& request) {
  Parameters p = request_parameters(request);
  auto s = std::make_shared<SkydomeRender::Settings>();
  const ModelFactory& factory = parse_model(p, context.models);
  s->model_id = factory.descriptor->id;
  s->sun = parse_sun(p);
  s->viewpoint = parse_viewpoint(p);
  ModelConfig config = parse_config(p, *factory.descriptor);
  s->png = p.choice("format", {"exr", "png"}, "exr") == "png";
  s->projection_name = p.choice("projection", {"fisheye", "latlong", "cubemap"}, "fisheye");
  const auto size_text = p.text("size");
  // 512 pixels unless the server's limit is lower: the limit bounds every image, the default
  // one included (a request without size ran past it; found by fuzz/api_routes_fuzz.cpp).
  const long long largest_even = context.limits.max_skydome_size / 2 * 2;
  long long size = largest_even < 512 ? largest_even : 512;
  if (size_text) {
    const double x = number_value("size", *size_text);
    if (x != std::floor(x) || x < 8) throw invalid_parameter("size", "must be an integer >= 8");
    if (x > context.limits.max_skydome_size) {
      throw too_large("size",
                      "at most " + std::to_string(context.limits.max_skydome_size) + " pixels");
    }
    size = static_cast<long long>(x);
  }
  if (s->projection_name == "latlong" && size % 2 != 0)
    throw invalid_parameter("size", "must be even for latlong");
  s->channels = p.choice("channels", {"rgb", "luminance", "spectral"}, "rgb");
  if (s->png) {
    // The PNG is a display image of the colour; pixel_type is the EXR's (unread: refused).
    if (s->channels != "rgb") throw invalid_parameter("channels", "format=png takes rgb only");
    s->half = false;
    s->exposure_ev100 =
        p.number_or("exposure", kDefaultExposureEv100, kMinExposureEv100, kMaxExposureEv100);
    s->tone_curve = tone_curve_named(p.choice("tone_map", {"aces", "reinhard"}, "aces"));
  } else {
    s->half = p.choice("pixel_type", {"half", "float"}, s->channels == "rgb" ? "half" : "float") ==
              "half";
  }
  s->method = "spectral";
  if (s->channels == "rgb") s->method = p.choice("method", {"spectral", "three"}, "spectral");
  std::optional<std::vector<double>> wavelengths;
  if (s->channels == "spectral") wavelengths = parse_wavelengths(p, context.limits);
  p.reject_unused();

  if (s->method == "three") {
    wavelengths = three_wavelength_method().grid().nanometres();
    config.wavelengths = three_wavelength_method().grid();
  }
  const Projection projection = s->projection_name == "fisheye"   ? Projection::fisheye
                                : s->projection_name == "latlong" ? Projection::latlong
                                                                  : Projection::cubemap;
  s->projection = SkydomeProjection(projection, static_cast<int>(size));
  s->m = model_on_wavelengths(context.models, factory, std::move(config), wavelengths,
                              request.requester());
  // The sun and the viewpoint are checked now, so that a sky the model cannot answer is an
  // error rather than a black image: one view at the zenith goes through the checked path.
  ViewList zenith;
  zenith.views.push_back({0.0, 0.0});
  zenith.zenith_deg.push_back(0.0);
  zenith.azimuth_deg.push_back(0.0);
  checked_sky_radiance(context.models, s->m.model, s->sun, s->viewpoint, zenith);
  s->sun_state = prepare_sun(context.models, s->m.model, s->sun);
  s->xyz = std::make_unique<XyzWeights>(s->m.model->wavelengths());
  return SkydomeRender(std::move(s));
}

const std::string& SkydomeRender::model_id() const { return settings_->model_id; }
int SkydomeRender::width() const { return settings_->projection.width(); }
int SkydomeRender::height() const { return settings_->projection.height(); }
const char* SkydomeRender::content_type() const {
  return settings_->png ? "image/png" : "image/x-exr";
}
const char* SkydomeRender::file_name() const { return settings_->png ? "sky.png" : "sky.exr"; }

std::size_t SkydomeRender::band_bytes() const {
  const Settings& s = *settings_;
  if (s.png) {
    // The float band, one 8-bit row, and libpng's and zlib's state (png_stream.h).
    return static_cast<std::size_t>(band_rows(s)) * static_cast<std::size_t>(s.projection.width()) *
               channel_count(s) * sizeof(float) +
           static_cast<std::size_t>(s.projection.width()) * 4 +
           PngStream::state_bytes(s.projection.width());
  }
  const std::size_t line_samples =
      static_cast<std::size_t>(s.projection.width()) * channel_count(s);
  const std::size_t sample_bytes = s.half ? 2 : 4;
  const std::size_t band_samples = static_cast<std::size_t>(band_rows(s)) * line_samples;
  // Besides the band: the scan line in OpenEXR's line buffer, and the scan line the sink is
  // sending (the HTTP layer copies each write into a chunk while the client reads it).
  return band_samples * sizeof(float) + (s.half ? band_samples * sample_bytes : 0) +
         2 * line_samples * sample_bytes;
}

bool SkydomeRender::write(const Sink& sink, unsigned threads,
                          std::size_t* unanswered_pixels) const {
  const Settings& s = *settings_;
  if (s.png) return write_png(s, sink, threads, unanswered_pixels);
  const int width = s.projection.width();
  const int height = s.projection.height();

  // Channels, in the order of the band buffer.
  std::vector<std::string> names;
  if (s.channels == "rgb")
    names = {"R", "G", "B"};
  else if (s.channels == "luminance")
    names = {"Y"};
  else
    for (double w : s.m.wavelengths_nm) names.push_back(spectral_channel_name(w));
  // Coverage: 1 where the model answered, 0 where it did not (outside the projection, below
  // the horizon of a ground-view model, outside a fitted model's domain), whose colour is 0;
  // without it such a 0 would be indistinguishable from a dark sky.
  names.push_back("A");
  const std::size_t n_channels = names.size();
  if (n_channels != channel_count(s))
    throw std::logic_error("skydome: channel_count() differs from the channels written");
  const Imf::PixelType type = s.half ? Imf::HALF : Imf::FLOAT;
  const std::size_t sample_bytes = s.half ? 2 : 4;

  Imf::Header header(width, height);
  header.compression() = Imf::NO_COMPRESSION;
  header.lineOrder() = Imf::INCREASING_Y;
  for (const auto& name : names) header.channels().insert(name, Imf::Channel(type));
  header.insert("clearskyModel", Imf::StringAttribute(s.model_id));
  header.insert("clearskyProjection", Imf::StringAttribute(s.projection_name));
  header.insert("sunZenithDeg", Imf::FloatAttribute(static_cast<float>(s.sun.zenith_deg)));
  header.insert("sunAzimuthDeg", Imf::FloatAttribute(static_cast<float>(s.sun.azimuth_deg)));
  header.insert(
      "clearskyAlpha",
      Imf::StringAttribute("A = 1 where the model answered, 0 where it did not (colour 0)"));
  header.insert("observerAltitudeM",
                Imf::FloatAttribute(static_cast<float>(s.viewpoint.altitude_m)));
  if (s.projection.projection() == Projection::latlong) Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
  if (s.projection.projection() == Projection::cubemap) Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
  if (s.channels == "rgb") {
    Imf::addChromaticities(header, Imf::Chromaticities());  // Rec. 709 primaries = sRGB, D65
    header.insert("clearskyColourMethod", Imf::StringAttribute(s.method));
    header.insert("clearskyGamutMapping", Imf::StringAttribute(kGamutMapping));
  }
  if (s.channels == "luminance") header.insert("luminanceUnits", Imf::StringAttribute("cd.m^-2"));
  if (s.channels == "spectral") {
    header.insert("spectralLayoutVersion", Imf::StringAttribute("1.0"));
    header.insert("emissiveUnits", Imf::StringAttribute("W.m^-2.sr^-1"));
  }

  ExrStream stream(sink);
  try {
    Imf::OutputFile file(stream, header, 0);
    const std::uint64_t line_bytes = static_cast<std::uint64_t>(width) * n_channels * sample_bytes;
    stream.start(uncompressed_chunk_offsets(stream.tellp(), height, line_bytes));

    // One band of rows: channel-interleaved float, then converted to half when asked.
    const int rows_per_band = band_rows(s);
    const std::size_t band_pixels =
        static_cast<std::size_t>(rows_per_band) * static_cast<std::size_t>(width);
    std::vector<float> band_float(band_pixels * n_channels);
    std::vector<half> band_half(s.half ? band_pixels * n_channels : 0);
    std::atomic<int> failed_pixels{0};
    for (int y0 = 0; y0 < height; y0 += rows_per_band) {
      const int rows = std::min(rows_per_band, height - y0);
      compute_band(s, y0, rows, band_float.data(), threads, failed_pixels);

      Imf::FrameBuffer frame;
      const std::size_t x_stride = n_channels * sample_bytes;
      const std::size_t y_stride = static_cast<std::size_t>(width) * x_stride;
      char* base = s.half ? reinterpret_cast<char*>(band_half.data())
                          : reinterpret_cast<char*>(band_float.data());
      if (s.half) {
        const std::size_t count =
            static_cast<std::size_t>(rows) * static_cast<std::size_t>(width) * n_channels;
        for (std::size_t i = 0; i < count; ++i) band_half[i] = half(band_float[i]);
      }
      // OpenEXR addresses pixel (x, y) at base + x * x_stride + y * y_stride: shift the base so
      // that row y0 is the band's first row.
      const std::ptrdiff_t shift =
          -static_cast<std::ptrdiff_t>(y0) * static_cast<std::ptrdiff_t>(y_stride);
      for (std::size_t c = 0; c < n_channels; ++c) {
        frame.insert(names[c],
                     Imf::Slice(type, base + shift + c * sample_bytes, x_stride, y_stride));
      }
      file.setFrameBuffer(frame);
      file.writePixels(rows);
    }
    if (unanswered_pixels != nullptr)
      *unanswered_pixels = static_cast<std::size_t>(failed_pixels.load());
  } catch (const StreamAborted&) {
    return false;
  } catch (const std::exception& e) {
    if (stream.aborted()) return false;
    throw;
  }
  if (!stream.matches_sent_table()) {
    throw std::logic_error("skydome: the EXR offset table sent differs from the one OpenEXR wrote");
  }
  return true;
}

}  // namespace clearsky::api
