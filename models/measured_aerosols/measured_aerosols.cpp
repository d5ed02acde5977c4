// measured_aerosols: descriptor and factory over the Bruneton engine.
#include "models/measured_aerosols/measured_aerosols.h"

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/embedded_data.h"
#include "models/core/invalid_input.h"
#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "models/measured_aerosols/measured_aerosol_optics.h"

namespace clearsky {

namespace {

constexpr const char* kInversionPath = "aeronet/130527_130527_Egbert.pfn";
// Ids are SQLite rowids; this bound keeps them within what the options parse as integers.
constexpr double kMaxAerosolsId = 2147483647.0;

std::vector<ParameterSpec> parameters() {
  std::vector<ParameterSpec> p = {
      {.name = kAerosolsOption,
       .description =
           "id of an uploaded AERONET inversion (POST /v1/aerosols); 0: the shipped Egbert "
           "2013-05-27 file. Names stored data: never swept or fitted",
       .default_value = 0.0,
       .min_value = 0.0,
       .max_value = kMaxAerosolsId,
       .integer = true},
      {.name = "retrieval_time_utc_h",
       .unit = "h",
       .description =
           "the inversion's retrieval nearest this time (hours UTC of the inversion's day); "
           "negative: the mean of the day's retrievals",
       .default_value = -1.0,
       .min_value = -1.0,
       .max_value = 24.0},
      {.name = "aod_scale",
       .description = "scale of the retrieved aerosol optical depth (1: as retrieved)",
       .default_value = 1.0,
       .min_value = 0.05,
       .max_value = 5.0},
  };
  // Bruneton's table options, as they are.
  for (const ParameterSpec& spec : bruneton_descriptor().parameters)
    if (!spec.atmosphere) p.push_back(spec);
  p.push_back(atmosphere_parameter_spec("mie_single_scattering_albedo"));
  p.push_back(atmosphere_parameter_spec("albedo"));
  return p;
}

// The shipped file for aerosols=0, else the uploaded inversion the installed source returns
// (aerosol_inversion_source.h); an id it does not know is refused naming aerosols.
std::shared_ptr<const BrunetonModel> build_selected(const ValidatedConfig& config,
                                                    const PrecomputeContext& context) {
  const auto id = static_cast<std::int64_t>(config.option(kAerosolsOption));
  if (id == 0) return build_measured_aerosols(config, context, default_aerosol_inversion());
  const std::optional<std::string> bytes = aerosol_inversion_bytes(id);
  if (!bytes) {
    throw InvalidInput(kAerosolsOption, "no aerosol inversion " + std::to_string(id));
  }
  return build_measured_aerosols(config, context, aeronet::parse_phase_function_file(*bytes));
}

}  // namespace

const ModelDescriptor& measured_aerosols_descriptor() {
  static const ModelDescriptor d{
      .id = "measured_aerosols",
      .name = "Bruneton 2008 with measured aerosols",
      .version = "1",
      .citation =
          "E. Bruneton and F. Neyret, Precomputed Atmospheric Scattering, Computer Graphics "
          "Forum 27(4) (EGSR 2008), 1079-1086; aerosols from the AERONET inversion of O. "
          "Dubovik and M. D. King, A flexible inversion algorithm for retrieval of aerosol "
          "optical properties from Sun and sky radiance measurements, JGR 105(D16) (2000), "
          "20673-20696",
      .summary =
          "The precomputed multiple scattering of Bruneton 2008 (same tables and options as "
          "the bruneton model) with the aerosols of the AERONET almucantar inversion of "
          "Egbert on 2013-05-27: optical depth from the retrieval's tau440 and Angstrom "
          "exponent (times aod_scale), the retrieved phase functions at 442, 674, 871 and "
          "1020 nm interpolated in angle and wavelength (single scattering per wavelength, "
          "the 550 nm one in the multiple-scattering precomputation), the retrieval nearest "
          "retrieval_time_utc_h or the day's mean.",
      .min_wavelength_nm = bruneton_descriptor().min_wavelength_nm,
      .max_wavelength_nm = bruneton_descriptor().max_wavelength_nm,
      .parameters = parameters(),
      .capabilities = bruneton_descriptor().capabilities,
  };
  return d;
}

ModelFactory measured_aerosols_factory() {
  ModelFactory factory = make_model_factory<&measured_aerosols_descriptor, &build_selected,
                                            &BrunetonModel::estimated_table_bytes>();
  // A ninth, optional model: its own 254.5 MB Bruneton-engine set (none shared with Bruneton's)
  // is paid only by a server asked for it (docs/tables-and-memory.md "The server with every
  // default ready").
  factory.standard_on_first_use = true;
  return factory;
}

const aeronet::PhaseFunctionFile& default_aerosol_inversion() {
  static const aeronet::PhaseFunctionFile file =
      aeronet::parse_phase_function_file(data::embedded_file(kInversionPath));
  return file;
}

std::shared_ptr<const BrunetonModel> build_measured_aerosols(
    const ValidatedConfig& config, const PrecomputeContext& context,
    const aeronet::PhaseFunctionFile& inversion) {
  const AtmosphereSpectra atmosphere =
      AtmosphereSpectra::build(config.config().atmosphere, config.config().wavelengths);
  const AerosolOptics optics = measured_aerosol_optics(
      inversion, config.option("retrieval_time_utc_h"), config.option("aod_scale"), atmosphere);
  return BrunetonModel::build_with_aerosols(config, context, optics);
}

}  // namespace clearsky
