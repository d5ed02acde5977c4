// The renderer options of GET /v1/skydome: the table and its parser.
#include "api/skydome/skydome_options.h"

#include <array>
#include <string>

#include "api/error/api_error.h"

namespace clearsky::api {

namespace {

const std::array<SkydomeOptionSpec, 4>& table() {
  static const std::array<SkydomeOptionSpec, 4> rows{{
      {"sun",
       {"none", "disc"},
       "none",
       "none: the sky only (the sun's light is in no pixel); disc: the limb-darkened solar disc "
       "(angular radius 0.2666 degrees, Neckel and Labs 1994 limb darkening as tabulated by Hosek "
       "and Wilkie 2013) carrying the model's direct normal irradiance: the pixels it covers "
       "integrate to it (spread over the pixel when the disc is smaller). The header's sun* "
       "attributes give its direction, irradiance and colour. Needs pixel_type=float (the "
       "default with disc).",
       false},
      {"ground",
       {"none", "albedo", "model"},
       "model for a model with views below the horizon, none otherwise",
       "Below the horizon. none: colour 0 and A = 0; albedo: a Lambertian ground of the "
       "atmosphere's albedo (grass unless albedo is given) lit by the model's direct and sky "
       "irradiance on the horizontal, A = 1; model: the model's own answer (bruneton, nishita93, "
       "oneal; 400 for the others), A = 1 where it answered.",
       false},
      {"units",
       {"radiometric", "photometric"},
       "radiometric",
       "channels=rgb only. radiometric: linear sRGB with Y in W/(m2.sr); photometric: the same "
       "times 683 lm/W, so that 0.2126 R + 0.7152 G + 0.0722 B is the luminance in cd/m2. Needs "
       "pixel_type=float (the default with photometric).",
       true},
      {"compression",
       {"none", "zip", "piz"},
       "none",
       "OpenEXR compression of the scan lines (lossless). none: the offset table is sent first; "
       "zip (16 lines a block) and piz (32): the blocks are sent as they are compressed and the "
       "offset table is zeros, which OpenEXR's readers rebuild by reading the blocks.",
       false},
  }};
  return rows;
}

// The row's value: absent -> fallback; otherwise one of its values, or a 400.
std::string_view value_of(Parameters& p, const SkydomeOptionSpec& row, std::string_view fallback) {
  const auto given = p.text(std::string(row.name));
  if (!given) return fallback;
  std::string list;
  for (std::string_view v : row.values) {
    if (v == *given) return v;
    list += (list.empty() ? "" : ", ") + std::string(v);
  }
  throw invalid_parameter(std::string(row.name), "'" + *given + "' is not one of " + list);
}

}  // namespace

std::span<const SkydomeOptionSpec> skydome_option_table() { return table(); }

SkydomeOptions parse_skydome_options(Parameters& p, bool rgb, const ModelDescriptor& descriptor) {
  const auto& rows = table();
  SkydomeOptions options;
  options.sun = value_of(p, rows[0], "none") == "disc" ? SunDisc::disc : SunDisc::none;

  const bool has_ground = descriptor.capabilities.view_below_horizon;
  const std::string_view ground = value_of(p, rows[1], has_ground ? "model" : "none");
  if (ground == "model" && !has_ground) {
    throw invalid_parameter("ground", "model " + descriptor.id +
                                          " has no ground (no views below the horizon): use "
                                          "none or albedo");
  }
  options.ground = ground == "none"     ? Ground::none
                   : ground == "albedo" ? Ground::albedo
                                        : Ground::model;
  if (rgb) {
    options.units = value_of(p, rows[2], "radiometric") == "photometric" ? PixelUnits::photometric
                                                                         : PixelUnits::radiometric;
  }
  const std::string_view compression = value_of(p, rows[3], "none");
  options.compression = compression == "zip"   ? ExrCompression::zip
                        : compression == "piz" ? ExrCompression::piz
                                               : ExrCompression::none;
  return options;
}

}  // namespace clearsky::api
