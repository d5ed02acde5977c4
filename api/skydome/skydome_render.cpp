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
#include <OpenEXR/ImfVecAttribute.h>

#include <algorithm>
#include <cstdio>

#include "api/colour/colour_wavelengths.h"
#include "api/colour/display_tone_mapping.h"
#include "api/colour/srgb_gamut.h"
#include "api/colour/xyz_weights.h"
#include "api/fits/stored_fit_values.h"
#include "api/handlers/sky_radiance_query.h"
#include "api/skydome/exr_compression.h"
#include "api/skydome/exr_stream.h"
#include "api/skydome/half_conversion.h"
#include "api/skydome/png_stream.h"
#include "api/skydome/skydome_ground.h"
#include "api/skydome/skydome_options.h"
#include "api/skydome/sun_disc.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/core/parallel.h"

namespace clearsky::api {

struct SkydomeRender::Settings {
  std::string model_id;
  RequestQuality quality;
  std::optional<AppliedFit> fit;  // the request's fit=, when given
  ModelOnGrid m;
  std::shared_ptr<const SunState> sun_state;
  SunSpec sun;
  Viewpoint viewpoint;
  SkydomeProjection projection{Projection::fisheye, 8};
  std::string channels;
  std::string method;
  // channels and method as flags for the per-pixel code, set with them in prepare_skydome().
  bool rgb_channels = false, spectral_channels = false, three_method = false;
  bool half = true;
  // format=png: 8-bit sRGB through display_tone_mapping.h, instead of the EXR.
  bool png = false;
  double exposure_ev100 = kDefaultExposureEv100;
  ToneCurve tone_curve = ToneCurve::aces;
  std::string projection_name;
  std::unique_ptr<XyzWeights> xyz;
  // The level's colour grid when it is not the model's own (api/colour/colour_wavelengths.h).
  std::optional<std::vector<double>> colour_wavelengths_nm;
  SkydomeOptions options;
  // The model's direct normal irradiance, W/(m2.nm) on its grid, when it has one for this sun
  // above the horizon (the header's sun attributes; the disc).
  std::optional<Spectrum> sun_irradiance;
  std::unique_ptr<SolarDiscPixels> disc;  // sun=disc
  Spectrum ground_radiance;               // ground=albedo, W/(m2.sr.nm) on the model's grid
  // ground=albedo: the channels of a ground pixel without the disc (write_pixel() of
  // ground_radiance), which the rows below a latlong map's horizon repeat.
  std::vector<float> ground_pixel;
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

// R, G, B of a pixel, mapped into the sRGB gamut (api/colour/srgb_gamut.h), times scale (683
// lm/W for units=photometric, 1 for radiometric).
void write_rgb(float* pixel, const LinearSrgb& colour, double scale) {
  const LinearSrgb c = clip_to_srgb_gamut(colour).rgb;
  pixel[0] = static_cast<float>(scale * c.r);
  pixel[1] = static_cast<float>(scale * c.g);
  pixel[2] = static_cast<float>(scale * c.b);
}

const ThreeWavelengthRgb& three_wavelength_method() {
  static const ThreeWavelengthRgb method;
  return method;
}

// Channels of the image, alpha included (the order is write()'s).
std::size_t channel_count(const SkydomeRender::Settings& s) {
  if (s.rgb_channels) return 4;
  if (!s.spectral_channels) return 2;  // luminance
  return s.m.wavelengths_nm.size() + 1;
}

// Rows of a band (kBandTargetBytes).
int band_rows(const SkydomeRender::Settings& s) {
  const std::size_t row_bytes =
      static_cast<std::size_t>(s.projection.width()) * channel_count(s) * sizeof(float);
  return static_cast<int>(std::clamp<std::size_t>(kBandTargetBytes / row_bytes, 1,
                                                  static_cast<std::size_t>(kMaxBandRows)));
}

std::string ground_name(Ground ground) {
  switch (ground) {
    case Ground::albedo:
      return "albedo";
    case Ground::model:
      return "model";
    case Ground::none:
      break;
  }
  return "none";
}

std::string alpha_rule(Ground ground) {
  switch (ground) {
    case Ground::albedo:
      return "A = 1 where the sky or the Lambertian ground has a value (below the horizon: "
             "albedo / pi x the model's sun and sky irradiance), 0 where the model did not "
             "answer (colour 0)";
    case Ground::model:
      return "A = 1 where the model answered (below the horizon: its own ground), 0 where it did "
             "not (colour 0)";
    case Ground::none:
      break;
  }
  return "A = 1 where the model answered above the horizon, 0 below the horizon and where it did "
         "not answer (colour 0)";
}

// The sun in the header (docs/renderers.md): its direction in OpenEXR's environment-map frame,
// its disc, and its direct normal irradiance and the disc's mean radiance in the image's units.
void add_sun_attributes(Imf::Header& header, const SkydomeRender::Settings& s) {
  const Vec3 d = SkydomeProjection::to_openexr_frame(SkyDirection{s.sun.sun});
  header.insert("sunDirection",
                Imf::V3fAttribute(IMATH_NAMESPACE::V3f(
                    static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z))));
  header.insert("sunAngularRadiusDeg",
                Imf::FloatAttribute(static_cast<float>(kSunAngularRadiusDeg)));
  header.insert("clearskySun",
                Imf::StringAttribute(
                    s.options.sun == SunDisc::disc
                        ? (s.disc && !s.disc->pixels().empty()
                               ? "disc: limb-darkened (Neckel and Labs 1994), its pixels "
                                 "integrate to the direct normal irradiance"
                               : "disc: below the horizon, in no pixel")
                        : "none: the sun's light is in no pixel; the sun* attributes give it"));
  if (!s.sun_irradiance) return;
  const Spectrum& e = *s.sun_irradiance;
  const double disc_sr = sun_disc_solid_angle_sr();
  // Direct normal illuminance, lx, and the colour of the direct light.
  Xyz xyz{};
  if (s.method == "three") {
    const LinearSrgb c =
        three_wavelength_method().rgb(e[s.m.indices[2]], e[s.m.indices[1]], e[s.m.indices[0]]);
    xyz = linear_srgb_to_xyz(c);
  } else {
    xyz = s.xyz->xyz(e.values());
  }
  header.insert("sunIlluminanceLx",
                Imf::FloatAttribute(static_cast<float>(kMaxLuminousEfficacy * xyz.y)));
  if (s.channels == "rgb") {
    const double scale = s.options.units == PixelUnits::photometric ? kMaxLuminousEfficacy : 1.0;
    const LinearSrgb c = clip_to_srgb_gamut(xyz_to_linear_srgb(xyz)).rgb;
    const auto v3 = [](double r, double g, double b) {
      return Imf::V3fAttribute(IMATH_NAMESPACE::V3f(static_cast<float>(r), static_cast<float>(g),
                                                    static_cast<float>(b)));
    };
    header.insert("sunIrradianceRGB", v3(scale * c.r, scale * c.g, scale * c.b));
    header.insert("sunRadianceRGB",
                  v3(scale * c.r / disc_sr, scale * c.g / disc_sr, scale * c.b / disc_sr));
    const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    if (y > 0.0) header.insert("sunColour", v3(c.r / y, c.g / y, c.b / y));
  }
}

// Whether a pixel's colour is a function of its XYZ alone (channels rgb or luminance by the
// spectral method), which the fast path then computes for a whole piece at once.
bool colour_from_xyz(const SkydomeRender::Settings& s) {
  return !s.spectral_channels && !s.three_method;
}

// The channels of a pixel whose colour is a function of its XYZ (colour_from_xyz), A = 1 last.
void write_xyz_colour(const SkydomeRender::Settings& s, float* px, const Xyz& xyz) {
  px[channel_count(s) - 1] = 1.0f;
  if (s.rgb_channels) {
    const double rgb_scale =
        s.options.units == PixelUnits::photometric ? kMaxLuminousEfficacy : 1.0;
    write_rgb(px, xyz_to_linear_srgb(xyz), rgb_scale);
  } else {
    px[0] = static_cast<float>(kMaxLuminousEfficacy * xyz.y);
  }
}

// One pixel's channels (channel_count(s) floats, channel-interleaved, A = 1 last) from its
// spectral radiance l on the model's grid.
void write_pixel(const SkydomeRender::Settings& s, float* px, std::span<const double> l) {
  const std::size_t alpha_channel = channel_count(s) - 1;
  const double rgb_scale = s.options.units == PixelUnits::photometric ? kMaxLuminousEfficacy : 1.0;
  px[alpha_channel] = 1.0f;
  if (s.spectral_channels) {
    for (std::size_t c = 0; c < alpha_channel; ++c) px[c] = static_cast<float>(l[s.m.indices[c]]);
  } else if (s.three_method) {
    const LinearSrgb c =
        three_wavelength_method().rgb(l[s.m.indices[2]], l[s.m.indices[1]], l[s.m.indices[0]]);
    if (s.rgb_channels) {
      write_rgb(px, c, rgb_scale);
    } else {
      px[0] = static_cast<float>(kMaxLuminousEfficacy * linear_srgb_to_xyz(c).y);
    }
  } else {
    write_xyz_colour(s, px, s.xyz->xyz(l));
  }
}

// A pixel's radiance l, plus the sun's disc (sun_disc.h) when the disc covers pixel (x, y) of
// a row it crosses (disc_row): then the sum is written into buffer and returned.
std::span<const double> with_disc(const SkydomeRender::Settings& s, int x, int y, bool disc_row,
                                  std::span<const double> l, std::vector<double>& buffer) {
  if (!disc_row) return l;
  const SolarDiscPixels::Pixel* sun_pixel = s.disc->find(x, y);
  if (sun_pixel == nullptr) return l;
  buffer.assign(l.begin(), l.end());
  for (std::size_t w = 0; w < buffer.size(); ++w) buffer[w] += sun_pixel->radiance[w];
  return buffer;
}

// The pixels [x_begin, x_end) of row y sorted by what answers them: the views the model is
// asked (views, their columns) and the ground's pixels below the horizon (ground_columns);
// pixels outside the projection and hidden ground are in neither. Appends to the three lists.
void gather_views(const SkydomeRender::Settings& s, int y, int x_begin, int x_end,
                  std::vector<ViewDirection>& views, std::vector<int>& columns,
                  std::vector<int>& ground_columns) {
  for (int x = x_begin; x < x_end; ++x) {
    SkyDirection d;
    if (!s.projection.direction(x, y, d)) continue;
    // Below the horizon (skydome_options.h): hidden, the albedo ground, or the model.
    if (d.zenith_rad > 0.5 * kPi && s.options.ground != Ground::model) {
      if (s.options.ground == Ground::albedo) ground_columns.push_back(x);
      continue;
    }
    views.push_back(d);
    columns.push_back(x);
  }
}

// The pixels [x_begin, x_end) of row y (row: the row's first pixel) one by one: each pixel's
// direction, the sky the model answers, the ground below the horizon (skydome_options.h) and
// the sun's disc (sun_disc.h).
void compute_pixels(const SkydomeRender::Settings& s, int y, int x_begin, int x_end, float* row,
                    std::atomic<int>& failed_pixels) {
  const std::size_t n_channels = channel_count(s);
  std::vector<ViewDirection> views;
  std::vector<int> columns, ground_columns;
  views.reserve(static_cast<std::size_t>(x_end - x_begin));
  gather_views(s, y, x_begin, x_end, views, columns, ground_columns);
  SpectralBatch batch;
  if (!views.empty()) s.m.model->sky_radiance(*s.sun_state, s.viewpoint, views, batch);
  const bool disc_row = s.disc && s.disc->covers_row(y);
  std::vector<double> with_sun;
  const auto emit = [&](int x, std::span<const double> l) {
    write_pixel(s, row + static_cast<std::size_t>(x) * n_channels,
                with_disc(s, x, y, disc_row, l, with_sun));
  };
  for (int x : ground_columns) emit(x, s.ground_radiance.values());
  for (std::size_t k = 0; k < views.size(); ++k) {
    if (batch.status[k] != SampleStatus::ok) {
      if (batch.status[k] != SampleStatus::view_below_horizon_unsupported) ++failed_pixels;
      continue;
    }
    emit(columns[k], batch.spectrum(k));
  }
}

// What a worker of the fast path reuses from piece to piece, so that a piece allocates nothing
// once the first has sized them.
struct PieceScratch {
  std::vector<ViewDirection> views;
  std::vector<int> columns, ground_columns;
  SpectralBatch batch;
  std::vector<Xyz> xyz;
  std::vector<double> with_sun;
};

// compute_pixels() on the fast path: the same pixels (every float the same), with the piece's
// buffers reused, and, when the colour is a function of the XYZ, the XYZ of every answered
// view of the piece in one pass (XyzWeights::xyz_of_rows, bit for bit xyz() of each).
void compute_pixels_fast(const SkydomeRender::Settings& s, int y, int x_begin, int x_end,
                         float* row, std::atomic<int>& failed_pixels, PieceScratch& scratch) {
  const std::size_t n_channels = channel_count(s);
  std::vector<ViewDirection>& views = scratch.views;
  std::vector<int>& columns = scratch.columns;
  std::vector<int>& ground_columns = scratch.ground_columns;
  views.clear();
  columns.clear();
  ground_columns.clear();
  gather_views(s, y, x_begin, x_end, views, columns, ground_columns);
  SpectralBatch& batch = scratch.batch;
  if (!views.empty()) s.m.model->sky_radiance(*s.sun_state, s.viewpoint, views, batch);
  const bool xyz_colour = colour_from_xyz(s);
  if (xyz_colour && !views.empty()) {
    scratch.xyz.resize(views.size());
    s.xyz->xyz_of_rows(batch.values.data(), batch.wavelength_count, views.size(),
                       scratch.xyz.data());
  }
  const bool disc_row = s.disc && s.disc->covers_row(y);
  const auto emit = [&](int x, std::span<const double> l) {
    write_pixel(s, row + static_cast<std::size_t>(x) * n_channels,
                with_disc(s, x, y, disc_row, l, scratch.with_sun));
  };
  for (int x : ground_columns) emit(x, s.ground_radiance.values());
  for (std::size_t k = 0; k < views.size(); ++k) {
    if (batch.status[k] != SampleStatus::ok) {
      if (batch.status[k] != SampleStatus::view_below_horizon_unsupported) ++failed_pixels;
      continue;
    }
    const int x = columns[k];
    if (xyz_colour && !(disc_row && s.disc->find(x, y) != nullptr)) {
      write_xyz_colour(s, row + static_cast<std::size_t>(x) * n_channels, scratch.xyz[k]);
    } else {
      emit(x, batch.spectrum(k));
    }
  }
}

// Whether row y of a latlong map is wholly below the horizon with nothing but the ground's
// pixel (or nothing) in it: no model answer there (ground albedo or none) and no disc pixel.
bool row_is_plain_ground(const SkydomeRender::Settings& s, int y) {
  return s.options.ground != Ground::model && !(s.disc && s.disc->covers_row(y)) &&
         s.projection.latlong_row_below_horizon(y);
}

// Rows [y0, y0 + rows) of the image into band (rows x width pixels of channel_count(s) floats,
// channel-interleaved, the coverage A last), over the cores in pieces of kPiecePixels. Both
// writers (the EXR and the PNG) take their pixels from here. The fast path fills the plain
// ground rows with s.ground_pixel, the pixel compute_pixels() writes for every one of them
// (the same function of the same radiance), so both paths give the same floats, and computes
// the other pixels with compute_pixels_fast(), one PieceScratch per worker (scratch: at least
// worker_count(threads) of them; unused on the per-pixel path).
// With band_half (half pixels), each piece is also converted to half on the core that computed
// it, rather than the whole band afterwards on the writing thread (the per-pixel path keeps
// that serial conversion, as earlier releases did); the conversion gives the same bits
// (half_conversion.h).
void compute_band(const SkydomeRender::Settings& s, int y0, int rows, float* band, unsigned threads,
                  std::atomic<int>& failed_pixels, SkydomePixelPath path,
                  std::vector<PieceScratch>& scratch, half* band_half = nullptr) {
  const int width = s.projection.width();
  const std::size_t n_channels = channel_count(s);
  const std::size_t pieces = static_cast<std::size_t>((width + kPiecePixels - 1) / kPiecePixels);
  const std::size_t tasks = static_cast<std::size_t>(rows) * pieces;
  const auto piece = [&](std::size_t task, PieceScratch* piece_scratch) {
    const std::size_t r = task / pieces;
    const int y = y0 + static_cast<int>(r);
    const int x_begin = static_cast<int>(task % pieces) * kPiecePixels;
    const int x_end = std::min(width, x_begin + kPiecePixels);
    float* row = band + r * static_cast<std::size_t>(width) * n_channels;
    float* first = row + static_cast<std::size_t>(x_begin) * n_channels;
    float* last = row + static_cast<std::size_t>(x_end) * n_channels;
    if (path == SkydomePixelPath::fast && row_is_plain_ground(s, y)) {
      if (s.options.ground == Ground::albedo) {
        for (float* px = first; px != last; px += n_channels)
          std::copy(s.ground_pixel.begin(), s.ground_pixel.end(), px);
      } else {
        std::fill(first, last, 0.0f);
      }
    } else {
      std::fill(first, last, 0.0f);
      if (piece_scratch != nullptr) {
        compute_pixels_fast(s, y, x_begin, x_end, row, failed_pixels, *piece_scratch);
      } else {
        compute_pixels(s, y, x_begin, x_end, row, failed_pixels);
      }
    }
    if (band_half != nullptr)
      floats_to_halves(first, band_half + (first - band), static_cast<std::size_t>(last - first));
  };
  if (path == SkydomePixelPath::per_pixel) {
    parallel_for(
        tasks, [&](std::size_t task) { piece(task, nullptr); }, threads);
    return;
  }
  // One call per worker, each taking pieces in turn until none is left (the dynamic schedule
  // of parallel_for, with the worker's own scratch).
  const std::size_t workers = std::min<std::size_t>(worker_count(threads), tasks);
  if (scratch.size() < workers)
    throw std::logic_error("skydome: fewer scratch buffers than workers");
  std::atomic<std::size_t> next{0};
  parallel_for(
      workers,
      [&](std::size_t worker) {
        for (std::size_t task = next.fetch_add(1); task < tasks; task = next.fetch_add(1))
          piece(task, &scratch[worker]);
      },
      threads);
}

// The PNG form (format=png): each band tone-mapped (display_tone_mapping.h) into 8-bit RGBA rows,
// alpha 255 where the model answered and 0 where it did not, each row given to libpng as it is
// made and each band flushed to the client. False when the client stopped reading.
bool write_png(const SkydomeRender::Settings& s, const SkydomeRender::Sink& sink, unsigned threads,
               std::size_t* unanswered_pixels, SkydomePixelPath path) {
  const int width = s.projection.width();
  const int height = s.projection.height();
  const DisplayToneMapping display(s.exposure_ev100, s.tone_curve);
  char exposure[32];
  std::snprintf(exposure, sizeof exposure, "%g", s.exposure_ev100);
  std::vector<std::pair<std::string, std::string>> text = {
      {"Software", "clearsky GET /v1/skydome"},
      {"clearskyModel", s.model_id},
      {"clearskyProjection", s.projection_name},
      {"sunZenithDeg", std::to_string(s.sun.zenith_deg)},
      {"sunAzimuthDeg", std::to_string(s.sun.azimuth_deg)},
      {"clearskyExposureEV100", exposure},
      {"clearskyToneMap", s.tone_curve == ToneCurve::aces ? "aces" : "reinhard"},
      {"clearskyAlpha", "255 where the model answered, 0 where it did not"},
      {"clearskyQuality", std::string(to_string(s.quality.level))},
      {"clearskyServedQuality", std::string(to_string(s.m.served_quality))},
      {"clearskyQualityDetail", quality_summary(s.quality, s.m.served_quality)}};
  if (s.fit) text.emplace_back("clearskyFit", fit_summary(*s.fit));
  PngStream png(sink, width, height, text);
  if (png.aborted()) return false;
  const std::size_t n_channels = channel_count(s);
  const int rows_per_band = band_rows(s);
  std::vector<float> band(static_cast<std::size_t>(rows_per_band) *
                          static_cast<std::size_t>(width) * n_channels);
  std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 4);
  std::atomic<int> failed_pixels{0};
  std::vector<PieceScratch> scratch(worker_count(threads));
  for (int y0 = 0; y0 < height; y0 += rows_per_band) {
    const int rows = std::min(rows_per_band, height - y0);
    compute_band(s, y0, rows, band.data(), threads, failed_pixels, path, scratch);
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
  SkyConfig sky = parse_sky_config(p, *factory.descriptor, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  s->fit = std::move(sky.fit);
  s->quality = parse_quality(p, *factory.descriptor, config, context.default_quality);
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
  s->options = parse_skydome_options(p, s->channels == "rgb", *factory.descriptor);
  if (s->png) {
    // The PNG is a display image of the colour; pixel_type and compression are the EXR's, and
    // its scale is the exposure (of radiometric values): all three refused.
    if (s->channels != "rgb") throw invalid_parameter("channels", "format=png takes rgb only");
    if (s->options.units == PixelUnits::photometric)
      throw invalid_parameter("units",
                              "format=png is exposed from radiometric values (exposure); "
                              "units=photometric is the EXR's");
    if (s->options.compression != ExrCompression::none)
      throw invalid_parameter("compression",
                              "format=png is always deflate-compressed; "
                              "compression is the EXR's");
    s->half = false;
    s->exposure_ev100 =
        p.number_or("exposure", kDefaultExposureEv100, kMinExposureEv100, kMaxExposureEv100);
    s->tone_curve = tone_curve_named(p.choice("tone_map", {"aces", "reinhard"}, "aces"));
  } else {
    // half (at most 65504) holds a radiometric sky, not the sun's disc (about 1e7 W/(m2.sr)) nor
    // photometric values (the sky near the sun reaches 1e5 cd/m2): float is their default, and
    // half with them a 400 rather than infinities.
    const bool needs_float =
        s->options.sun == SunDisc::disc || s->options.units == PixelUnits::photometric;
    s->half = p.choice("pixel_type", {"half", "float"},
                       s->channels == "rgb" && !needs_float ? "half" : "float") == "half";
    if (s->half && needs_float) {
      throw invalid_parameter("pixel_type", s->options.sun == SunDisc::disc
                                                ? "half cannot hold the sun's disc (sun=disc): use "
                                                  "float"
                                                : "half cannot hold photometric values: use float");
    }
  }
  s->method = "spectral";
  if (s->channels == "rgb") s->method = p.choice("method", {"spectral", "three"}, "spectral");
  s->rgb_channels = s->channels == "rgb";
  s->spectral_channels = s->channels == "spectral";
  s->three_method = s->method == "three";
  std::optional<std::vector<double>> wavelengths;
  if (s->channels == "spectral") wavelengths = parse_wavelengths(p, context.limits);
  p.reject_unused();

  if (s->method == "three") {
    wavelengths = three_wavelength_method().grid().nanometres();
    config.wavelengths = three_wavelength_method().grid();
  } else if (s->channels != "spectral") {
    // Colour only: the level's colour grid (docs/quality-levels.md "Colour wavelengths").
    s->colour_wavelengths_nm = colour_wavelengths_nm(s->quality.level);
    if (s->colour_wavelengths_nm) wavelengths = s->colour_wavelengths_nm;
  }
  const Projection projection = s->projection_name == "fisheye"   ? Projection::fisheye
                                : s->projection_name == "latlong" ? Projection::latlong
                                                                  : Projection::cubemap;
  s->projection = SkydomeProjection(projection, static_cast<int>(size));
  s->m = model_on_wavelengths(context.models, factory, std::move(config), wavelengths,
                              request.requester(), &s->quality);
  // The sun and the viewpoint are checked now, so that a sky the model cannot answer is an
  // error rather than a black image: one view at the zenith goes through the checked path.
  ViewList zenith;
  zenith.views.push_back({0.0, 0.0});
  zenith.zenith_deg.push_back(0.0);
  zenith.azimuth_deg.push_back(0.0);
  checked_sky_radiance(context.models, s->m.model, s->sun, s->viewpoint, zenith);
  s->sun_state = prepare_sun(context.models, s->m.model, s->sun);
  s->xyz = s->colour_wavelengths_nm
               ? std::make_unique<XyzWeights>(XyzWeights::interpolating(s->m.model->wavelengths()))
               : std::make_unique<XyzWeights>(s->m.model->wavelengths());
  const SkyModel& model = *s->m.model;
  // The sun's light, for the disc and the header: only while some of the disc is above the
  // horizon (the ground hides the rest).
  const bool sun_visible = s->sun.zenith_deg < 90.0 + kSunAngularRadiusDeg;
  if (sun_visible && model.descriptor().capabilities.sun_irradiance) {
    const SpectralSample direct = model.sun_irradiance(*s->sun_state, s->viewpoint);
    if (direct.status == SampleStatus::ok) s->sun_irradiance = direct.value;
    if (s->options.sun == SunDisc::disc) require_answer(direct.status, "sun", s->model_id);
  } else if (sun_visible && s->options.sun == SunDisc::disc) {
    throw cannot_answer("sun", s->model_id, "it does not compute the direct sun irradiance");
  }
  if (s->options.sun == SunDisc::disc && s->sun_irradiance) {
    const WavelengthGrid& grid = model.wavelengths();
    std::vector<double> nm(grid.size());
    for (std::size_t w = 0; w < grid.size(); ++w) nm[w] = grid[w];
    s->disc = std::make_unique<SolarDiscPixels>(s->projection, SkyDirection{s->sun.sun}, nm,
                                                *s->sun_irradiance);
  }
  if (s->options.ground == Ground::albedo) {
    s->ground_radiance = lambertian_ground_radiance(model, *s->sun_state, s->viewpoint);
    s->ground_pixel.assign(channel_count(*s), 0.0f);
    write_pixel(*s, s->ground_pixel.data(), s->ground_radiance.values());
  }
  return SkydomeRender(std::move(s));
}

const std::string& SkydomeRender::model_id() const { return settings_->model_id; }
void SkydomeRender::add_quality_headers(
    std::vector<std::pair<std::string, std::string>>& headers) const {
  api::add_quality_headers(headers, settings_->quality, settings_->m.served_quality);
}
void SkydomeRender::add_fit_headers(
    std::vector<std::pair<std::string, std::string>>& headers) const {
  api::add_fit_headers(headers, settings_->fit);
}
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
           PngStream::state_bytes(s.projection.width()) + (s.disc ? s.disc->memory_bytes() : 0);
  }
  const std::size_t line_samples =
      static_cast<std::size_t>(s.projection.width()) * channel_count(s);
  const std::size_t sample_bytes = s.half ? 2 : 4;
  const std::size_t band_samples = static_cast<std::size_t>(band_rows(s)) * line_samples;
  // Besides the band: the scan line in OpenEXR's line buffer, and the scan line the sink is
  // sending (the HTTP layer copies each write into a chunk while the client reads it).
  const std::size_t line_bytes = line_samples * sample_bytes;
  // Compressed: OpenEXR's block and compressor buffers, and a compressed block being sent.
  const std::size_t writer_bytes =
      s.options.compression == ExrCompression::none
          ? 2 * line_bytes
          : compressor_bytes(s.options.compression, line_bytes) +
                static_cast<std::size_t>(lines_per_block(s.options.compression)) * line_bytes;
  return band_samples * sizeof(float) + (s.half ? band_samples * sample_bytes : 0) + writer_bytes +
         (s.disc ? s.disc->memory_bytes() : 0);
}

bool SkydomeRender::write(const Sink& sink, unsigned threads, std::size_t* unanswered_pixels,
                          SkydomePixelPath path) const {
  const Settings& s = *settings_;
  if (s.png) return write_png(s, sink, threads, unanswered_pixels, path);
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
  header.compression() = openexr_compression(s.options.compression);
  header.lineOrder() = Imf::INCREASING_Y;
  for (const auto& name : names) header.channels().insert(name, Imf::Channel(type));
  header.insert("clearskyModel", Imf::StringAttribute(s.model_id));
  header.insert("clearskyProjection", Imf::StringAttribute(s.projection_name));
  // The quality asked, the one whose tables answered, and the setting with its error figures
  // (docs/quality-levels.md).
  header.insert("clearskyQuality", Imf::StringAttribute(std::string(to_string(s.quality.level))));
  header.insert("clearskyServedQuality",
                Imf::StringAttribute(std::string(to_string(s.m.served_quality))));
  header.insert("clearskyQualityDetail",
                Imf::StringAttribute(quality_summary(s.quality, s.m.served_quality)));
  // The stored fit whose values the request used (docs/fits.md "Using a fit").
  if (s.fit) header.insert("clearskyFit", Imf::StringAttribute(fit_summary(*s.fit)));
  header.insert("sunZenithDeg", Imf::FloatAttribute(static_cast<float>(s.sun.zenith_deg)));
  header.insert("sunAzimuthDeg", Imf::FloatAttribute(static_cast<float>(s.sun.azimuth_deg)));
  header.insert("clearskyAlpha", Imf::StringAttribute(alpha_rule(s.options.ground)));
  header.insert("clearskyGround", Imf::StringAttribute(ground_name(s.options.ground)));
  add_sun_attributes(header, s);
  header.insert("observerAltitudeM",
                Imf::FloatAttribute(static_cast<float>(s.viewpoint.altitude_m)));
  if (s.projection.projection() == Projection::latlong) Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
  if (s.projection.projection() == Projection::cubemap) Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
  if (s.channels == "rgb") {
    Imf::addChromaticities(header, Imf::Chromaticities());  // Rec. 709 primaries = sRGB, D65
    header.insert("clearskyColourMethod", Imf::StringAttribute(s.method));
  }
  if (s.colour_wavelengths_nm) {
    // A draft colour: the wavelengths it was computed on and its error against the
    // 40-wavelength colour (docs/quality-levels.md "Colour wavelengths"). Standard and
    // reference colours are on the model's grid, and their files are unchanged.
    header.insert(
        "clearskyColourWavelengthsNm",
        Imf::StringAttribute(wavelength_list_text(s.m.model->wavelengths().nanometres())));
    header.insert(
        "clearskyColourError",
        Imf::StringAttribute(colour_error_text(
            s.quality.overridden.empty() ? draft_colour_error(s.model_id) : std::nullopt)));
  }
  if (s.channels == "rgb") {
    header.insert("clearskyGamutMapping", Imf::StringAttribute(kGamutMapping));
    const bool photometric = s.options.units == PixelUnits::photometric;
    header.insert("clearskyUnits",
                  Imf::StringAttribute(photometric ? "photometric: cd.m^-2 (683 lm/W x "
                                                     "radiometric; luminance = 0.2126 R + 0.7152 "
                                                     "G + 0.0722 B)"
                                                   : "radiometric: Y in W.m^-2.sr^-1"));
    // OpenEXR's standard attribute: the luminance, cd/m2, of R = G = B = 1.
    Imf::addWhiteLuminance(header, photometric ? 1.0f : static_cast<float>(kMaxLuminousEfficacy));
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
    if (s.options.compression == ExrCompression::none) {
      stream.start(uncompressed_chunk_offsets(stream.tellp(), height, line_bytes));
    } else {
      const int block = lines_per_block(s.options.compression);
      stream.start_with_zero_table(static_cast<std::size_t>((height + block - 1) / block));
    }

    // One band of rows: channel-interleaved float, then converted to half when asked.
    const int rows_per_band = band_rows(s);
    const std::size_t band_pixels =
        static_cast<std::size_t>(rows_per_band) * static_cast<std::size_t>(width);
    std::vector<float> band_float(band_pixels * n_channels);
    std::vector<half> band_half(s.half ? band_pixels * n_channels : 0);
    std::atomic<int> failed_pixels{0};
    std::vector<PieceScratch> scratch(worker_count(threads));
    for (int y0 = 0; y0 < height; y0 += rows_per_band) {
      const int rows = std::min(rows_per_band, height - y0);
      const bool convert_in_band = s.half && path == SkydomePixelPath::fast;
      compute_band(s, y0, rows, band_float.data(), threads, failed_pixels, path, scratch,
                   convert_in_band ? band_half.data() : nullptr);

      Imf::FrameBuffer frame;
      const std::size_t x_stride = n_channels * sample_bytes;
      const std::size_t y_stride = static_cast<std::size_t>(width) * x_stride;
      char* base = s.half ? reinterpret_cast<char*>(band_half.data())
                          : reinterpret_cast<char*>(band_float.data());
      if (s.half && !convert_in_band) {
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
