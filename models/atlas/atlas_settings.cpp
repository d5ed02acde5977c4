// The cost settings of each model (atlas_settings.h). The lists follow the cost options each
// model's README describes (models/<id>/README.md): the Bruneton and Elek table resolutions
// r x mu x mu_s x nu and scattering orders, Haber's layers, azimuth sectors, shell stride,
// orders and sun bucket, Nishita96's spheres, cylinders, table nodes, phase cells and sun
// bucket, the Nishita93 sphere and cylinder counts, O'Neal's ray samples, Hosek's native bands.
#include "models/atlas/atlas_settings.h"

#include <stdexcept>

#include "models/colour/three_wavelength_rgb.h"

namespace clearsky::atlas {

std::string to_string(AtlasGrid grid) {
  switch (grid) {
    case AtlasGrid::paper_bins:
      return "paper_bins";
    case AtlasGrid::rgb_points:
      return "rgb_points";
    case AtlasGrid::native_bands:
      return "native_bands";
  }
  return "paper_bins";
}

ModelConfig AtlasSetting::config(const ModelDescriptor& descriptor) const {
  ModelConfig config;
  config.options = options;
  switch (grid) {
    case AtlasGrid::paper_bins:
      config.wavelengths = WavelengthGrid::paper_bins();
      break;
    case AtlasGrid::rgb_points:
      config.wavelengths = ThreeWavelengthRgb().grid();
      break;
    case AtlasGrid::native_bands:
      if (descriptor.native_wavelengths_nm.empty())
        throw std::invalid_argument(descriptor.id + " has no native bands");
      config.wavelengths = WavelengthGrid::points(descriptor.native_wavelengths_nm);
      break;
  }
  return config;
}

namespace {

using Options = std::map<std::string, double>;

AtlasSetting setting(std::string name, Options options, AtlasGrid grid = AtlasGrid::paper_bins) {
  return {std::move(name), std::move(options), grid};
}

Options bruneton_tables(int r, int mu, int mu_s, int nu, int orders) {
  return {{"table_r_size", r},
          {"table_mu_size", mu},
          {"table_mu_s_size", mu_s},
          {"table_nu_size", nu},
          {"scattering_orders", orders}};
}

std::string tables_name(int r, int mu, int mu_s, int nu, int orders) {
  return std::to_string(r) + "x" + std::to_string(mu) + "x" + std::to_string(mu_s) + "x" +
         std::to_string(nu) + " orders=" + std::to_string(orders);
}

AtlasSetting tables(int r, int mu, int mu_s, int nu, int orders) {
  return setting(tables_name(r, mu, mu_s, nu, orders), bruneton_tables(r, mu, mu_s, nu, orders));
}

// Bruneton and Elek share the tables (models/elek/README.md): Elek's full list is shorter (the
// resolutions and orders measured for Bruneton hold for it), its reference the same and
// unchecked (Bruneton's check covers it), and it adds its native bands.
ModelAtlasSettings precomputed_tables(bool elek, AtlasScope scope) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  if (scope == AtlasScope::quick) {
    out.settings.push_back(tables(8, 32, 8, 4, 2));
    out.settings.push_back(tables(16, 64, 16, 4, 4));
    out.reference = tables(40, 160, 40, 10, 5);
    out.reference_reason =
        "quick: 1.25 times the paper's resolution on every axis and 5 orders, unchecked";
  } else {
    if (!elek) {
      for (int orders : {1, 3}) out.settings.push_back(tables(32, 128, 32, 8, orders));
      out.settings.push_back(tables(16, 128, 32, 8, 4));
      out.settings.push_back(tables(32, 64, 16, 8, 4));
    }
    out.settings.push_back(tables(32, 128, 32, 8, 2));
    out.settings.push_back(tables(16, 64, 16, 4, 4));
    out.settings.push_back(tables(8, 32, 8, 4, 4));
    out.settings.push_back(tables(8, 32, 8, 4, 2));
    out.reference = tables(48, 192, 48, 12, 6);
    out.reference_reason =
        "1.5 times the paper's resolution on every table axis and 6 scattering orders";
    if (elek) {
      out.reference_reason += " (the tables of Bruneton's reference, checked there)";
    } else {
      out.reference_check = tables(64, 256, 64, 16, 6);
      out.reference_reason +=
          "; checked against 2 times the paper's resolution (the orders converge along the "
          "list's orders 1 to 4)";
    }
  }
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  if (elek) out.settings.push_back(setting("native", {}, AtlasGrid::native_bands));
  return out;
}

ModelAtlasSettings haber(AtlasScope scope) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  auto h = [](int layers, int sectors, int stride, int orders, double bucket) {
    return Options{{"layers", layers},
                   {"azimuth_sectors", sectors},
                   {"shell_stride", stride},
                   {"scattering_orders", orders},
                   {"sun_zenith_bucket_deg", bucket}};
  };
  if (scope == AtlasScope::quick) {
    out.settings.push_back(setting("layers=25 sectors=36", h(25, 36, 4, 4, 1.0)));
    out.reference = setting("layers=75 orders=5 bucket=0", h(75, 72, 4, 5, 0.0));
    out.reference_reason = "quick: 1.5 times the layers, 5 orders, exact suns, unchecked";
  } else {
    for (int orders : {1, 2, 3})
      out.settings.push_back(
          setting("orders=" + std::to_string(orders), h(50, 72, 4, orders, 1.0)));
    out.settings.push_back(setting("layers=25 sectors=36", h(25, 36, 4, 4, 1.0)));
    out.settings.push_back(setting("stride=8", h(50, 72, 8, 4, 1.0)));
    out.settings.push_back(setting("bucket=5", h(50, 72, 4, 4, 5.0)));
    out.settings.push_back(setting("bucket=0", h(50, 72, 4, 4, 0.0)));
    out.reference = setting("layers=75 stride=2 orders=6 bucket=0", h(75, 72, 2, 6, 0.0));
    out.reference_check = setting("layers=100 stride=2 orders=6 bucket=0", h(100, 72, 2, 6, 0.0));
    out.reference_reason =
        "1.5 times the layers, half the shell stride, 6 orders and exact suns; checked against "
        "twice the layers (each finer step costs minutes per sun on the 2-core machine)";
  }
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  return out;
}

ModelAtlasSettings nishita96(AtlasScope scope) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  auto n = [](int rays, int nodes, int phase, double bucket) {
    return Options{{"spheres", rays},
                   {"cylinders", rays},
                   {"table_nodes", nodes},
                   {"phase_theta_cells", phase},
                   {"sun_zenith_bucket_deg", bucket}};
  };
  if (scope == AtlasScope::quick) {
    out.settings.push_back(setting("rays=32 nodes=17", n(32, 17, 32, 0.0)));
    out.reference = setting("rays=128 nodes=65 phase=64", n(128, 65, 64, 0.0));
    out.reference_reason = "quick: twice the rays and phase cells, 65 table nodes, unchecked";
  } else {
    out.settings.push_back(setting("nodes=17", n(64, 17, 32, 0.0)));
    out.settings.push_back(setting("nodes=9", n(64, 9, 32, 0.0)));
    out.settings.push_back(setting("rays=32", n(32, 33, 32, 0.0)));
    out.settings.push_back(setting("rays=16", n(16, 33, 32, 0.0)));
    out.settings.push_back(setting("rays=32 nodes=17", n(32, 17, 32, 0.0)));
    out.settings.push_back(setting("phase=16", n(64, 33, 16, 0.0)));
    out.settings.push_back(setting("bucket=1", n(64, 33, 32, 1.0)));
    out.settings.push_back(setting("bucket=5", n(64, 33, 32, 5.0)));
    out.reference = setting("rays=256 nodes=65 phase=128", n(256, 65, 128, 0.0));
    out.reference_check = setting("rays=512 nodes=65 phase=256", n(512, 65, 256, 0.0));
    out.reference_reason =
        "4 times the spheres, cylinders and phase cells, the most table nodes (65); checked "
        "against 8 times the rays and phase cells (65 nodes is the declared maximum)";
  }
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  return out;
}

ModelAtlasSettings nishita93(AtlasScope scope) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  auto n = [](int rays) { return Options{{"spheres", rays}, {"cylinders", rays}}; };
  if (scope == AtlasScope::quick) {
    out.settings.push_back(setting("rays=16", n(16)));
    out.reference = setting("rays=256", n(256));
    out.reference_reason = "quick: 4 times the spheres and cylinders, unchecked";
  } else {
    for (int rays : {8, 16, 32, 128})
      out.settings.push_back(setting("rays=" + std::to_string(rays), n(rays)));
    out.reference = setting("rays=512", n(512));
    out.reference_check = setting("rays=1024", n(1024));
    out.reference_reason =
        "8 times the paper's spheres and cylinders; checked against 16 times (the declared "
        "maximum)";
  }
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  return out;
}

ModelAtlasSettings oneal(AtlasScope scope) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  auto s = [](int samples) { return Options{{"samples", samples}}; };
  if (scope == AtlasScope::quick) {
    out.settings.push_back(setting("samples=2", s(2)));
    out.settings.push_back(setting("samples=16", s(16)));
    out.reference = setting("samples=256", s(256));
    out.reference_reason = "quick: 64 times the paper's ray samples, unchecked";
  } else {
    for (int samples : {1, 2, 8, 16, 32, 64})
      out.settings.push_back(setting("samples=" + std::to_string(samples), s(samples)));
    out.reference = setting("samples=512", s(512));
    out.reference_check = setting("samples=1024", s(1024));
    out.reference_reason =
        "128 times the paper's ray samples; checked against 256 times (the declared maximum)";
  }
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  return out;
}

// Fitted or analytic formulas: no discretisation to refine, so the reference is the standard
// setting on the paper's 40 bins, and the list measures the wavelength grids.
ModelAtlasSettings formula(bool has_native_bands, const std::string& native_option) {
  ModelAtlasSettings out;
  out.settings.push_back(setting("standard", {}));
  if (!native_option.empty())
    out.settings.push_back(setting(native_option + "=1", {{native_option, 1.0}}));
  out.settings.push_back(setting("rgb", {}, AtlasGrid::rgb_points));
  if (has_native_bands) out.settings.push_back(setting("native", {}, AtlasGrid::native_bands));
  out.reference = setting("standard", {});
  out.reference_reason =
      "a closed form with no numerical discretisation: the standard setting on the 40 bins is "
      "the model itself";
  return out;
}

}  // namespace

ModelAtlasSettings atlas_settings(const ModelDescriptor& descriptor, AtlasScope scope) {
  const std::string& id = descriptor.id;
  // measured_aerosols runs Bruneton's engine with the same table options
  // (models/measured_aerosols/README.md): Bruneton's list and reference.
  if (id == "bruneton" || id == "measured_aerosols") return precomputed_tables(false, scope);
  if (id == "elek") return precomputed_tables(true, scope);
  if (id == "haber") return haber(scope);
  if (id == "nishita96") return nishita96(scope);
  if (id == "nishita93") return nishita93(scope);
  if (id == "oneal") return oneal(scope);
  if (id == "preetham") return formula(false, "");
  if (id == "hosek") return formula(!descriptor.native_wavelengths_nm.empty(), "native_bands");
  throw std::invalid_argument("no atlas settings for model '" + id + "'");
}

}  // namespace clearsky::atlas
