// measured_aerosols: the Bruneton and Neyret 2008 engine (models/bruneton, all orders of
// scattering precomputed into 4D tables) with the aerosols of a day's AERONET almucantar
// inversion (Dubovik and King 2000) instead of the Angstrom law and the Cornette-Shanks phase
// function: the retrieval's optical depth spectrum and phase functions per wavelength
// (models/measured_aerosols/measured_aerosol_optics.h; README.md here). The inversion is the
// one in models/data/aeronet (Egbert, 2013-05-27, five retrievals), or with aerosols=ID an
// uploaded one, found through models/measured_aerosols/aerosol_inversion_source.h.
//
// | parameter                    | unit | default | range     | meaning                                                          |
// |------------------------------|------|---------|-----------|------------------------------------------------------------------|
// | aerosols                     | -    | 0       | [0, 2147483647] | an uploaded inversion's id (aerosol_inversion_source.h); 0: the shipped file |
// | retrieval_time_utc_h         | h    | -1      | [-1, 24]  | the retrieval nearest this UTC time; negative: the day's mean    |
// | aod_scale                    | -    | 1       | [0.05, 5] | scale of the retrieved aerosol optical depth                     |
// | scattering_orders            | -    | 4       | [1, 10]   | orders of scattering precomputed                                 |
// | table_r_size                 | -    | 32      | [3, 128]  | 4D tables: altitudes (RES_R)                                     |
// | table_mu_size                | -    | 128     | [4, 512]  | 4D tables: view zenith cosines (RES_MU, even)                    |
// | table_mu_s_size              | -    | 32      | [2, 128]  | 4D tables: sun zenith cosines (RES_MU_S)                         |
// | table_nu_size                | -    | 8       | [2, 64]   | 4D tables: view-sun cosines (RES_NU)                             |
// | max_sun_zenith_deg           | deg  | 101.39  | [95, 120] | sun range of the 4D and irradiance tables                        |
// | mie_single_scattering_albedo | -    | 0.8     | [0, 1]    | aerosol single-scattering albedo (atmosphere; not in the file)   |
// | albedo                       | -    | grass   | [0, 1]    | ground albedo; grass: Feister and Grewe, per lambda (atmosphere) |
// (atmosphere): the shared parameters of models/atmosphere/atmosphere_parameter_table.h. This
// table is checked against the descriptor by tests/models/contract/model_contract_test.cpp.
//
// Limits, capabilities and thread-safety: those of BrunetonModel (models/bruneton/bruneton.h).
#pragma once

#include "models/aeronet/aeronet_phase_functions.h"
#include "models/bruneton/bruneton.h"

namespace clearsky {

const ModelDescriptor& measured_aerosols_descriptor();
ModelFactory measured_aerosols_factory();

// The embedded inversion (models/data/aeronet/130527_130527_Egbert.pfn), parsed once.
const aeronet::PhaseFunctionFile& default_aerosol_inversion();

// Builds the model of a validated configuration from the given inversion.
std::shared_ptr<const BrunetonModel> build_measured_aerosols(
    const ValidatedConfig& config, const PrecomputeContext& context,
    const aeronet::PhaseFunctionFile& inversion);

}  // namespace clearsky
