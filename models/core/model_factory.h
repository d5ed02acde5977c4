// How every model is made (docs/model-contract.md "Adding a model"): the configuration is
// checked against the model's descriptor exactly once per build, by validated_config(), and the
// model's build function receives the proof of it, a ValidatedConfig, from which it reads its
// options (the descriptor's default where the configuration has none).
//
//   ModelFactory my_model_factory() {
//     return make_model_factory<&my_model_descriptor, &MyModel::build,
//                               &MyModel::estimated_table_bytes>();
//   }
//
// with `static std::shared_ptr<const MyModel> build(const ValidatedConfig&, const
// PrecomputeContext&)` and `static std::size_t estimated_table_bytes(const ValidatedConfig&)`. Checks the descriptor's ranges cannot express (an even table size)
// belong to the build function and throw InvalidInput naming the option.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "models/core/sky_model.h"

namespace clearsky {

// A ModelConfig that passed validate_config() against descriptor(). Holds references: the
// descriptor is static and the configuration outlives the build.
class ValidatedConfig {
 public:
  const ModelDescriptor& descriptor() const { return *descriptor_; }
  const ModelConfig& config() const { return *config_; }
  // The option's value, or the descriptor's default; std::logic_error for a name the
  // descriptor does not list (a model bug).
  double option(std::string_view name) const;
  int integer_option(std::string_view name) const { return static_cast<int>(option(name)); }

 private:
  friend ValidatedConfig validated_config(const ModelDescriptor&, const ModelConfig&);
  ValidatedConfig(const ModelDescriptor& descriptor, const ModelConfig& config)
      : descriptor_(&descriptor), config_(&config) {}

  const ModelDescriptor* descriptor_;
  const ModelConfig* config_;
};

// validate_config(descriptor, config) (InvalidInput naming the parameter), then the proof.
ValidatedConfig validated_config(const ModelDescriptor& descriptor, const ModelConfig& config);

// The Estimate of a model without precomputed tables (its table_bytes() is 0: Preetham, Hosek,
// O'Neal evaluate closed forms or fitted coefficients per query).
inline std::size_t no_precomputed_tables(const ValidatedConfig&) { return 0; }

// The factory of a model: its descriptor, a create() that validates once, then calls
// Build(validated, context), and an estimate_table_bytes() that validates, then calls
// Estimate(validated). Describe: const ModelDescriptor& (*)(); Build: a function
// (const ValidatedConfig&, const PrecomputeContext&) -> shared_ptr to a SkyModel; Estimate: a
// function (const ValidatedConfig&) -> std::size_t, the bytes the built model's table_bytes()
// will report (docs/model-contract.md "Table size").
template <const ModelDescriptor& (*Describe)(), auto Build, auto Estimate>
ModelFactory make_model_factory() {
  return ModelFactory{&Describe(),
                      [](const ModelConfig& config,
                         const PrecomputeContext& context) -> std::shared_ptr<const SkyModel> {
                        return Build(validated_config(Describe(), config), context);
                      },
                      [](const ModelConfig& config) -> std::size_t {
                        return Estimate(validated_config(Describe(), config));
                      }};
}

}  // namespace clearsky
