// The configurations built at start (start_builds.h).
#include "server/tables/start_builds.h"

#include <stdexcept>

namespace clearsky::server {

ModelConfig level_config(const ModelDescriptor& descriptor, QualityLevel level) {
  ModelConfig config;
  apply_quality_level(descriptor, quality_setting(descriptor.id, level), config.options);
  return config;
}

std::vector<std::pair<const ModelFactory*, ModelConfig>> start_builds(
    std::span<const ModelFactory> served, const std::vector<std::string>& prebuild) {
  std::vector<std::pair<const ModelFactory*, ModelConfig>> builds;
  if (prebuild.empty()) {
    const std::string defaults = ModelConfig{}.canonical_string();
    for (const ModelFactory& f : served) {
      ModelConfig draft = level_config(*f.descriptor, QualityLevel::draft);
      if (draft.canonical_string() != defaults) builds.emplace_back(&f, std::move(draft));
    }
    // A model whose standard is built on first use (ModelFactory::standard_on_first_use) gets
    // only its draft here: its first standard requests are answered from that draft while a
    // request's build of the standard runs.
    for (const ModelFactory& f : served) {
      if (!f.standard_on_first_use) builds.emplace_back(&f, ModelConfig{});
    }
    return builds;
  }
  for (const std::string& item : prebuild) {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos) {
      throw std::invalid_argument("'" + item + "' is not model:level (e.g. bruneton:standard)");
    }
    const std::string id = item.substr(0, colon);
    const auto level = parse_quality_level(item.substr(colon + 1));
    if (!level) {
      throw std::invalid_argument("'" + item + "': the level is draft, standard or reference");
    }
    const ModelFactory* factory = nullptr;
    for (const ModelFactory& f : served) {
      if (f.descriptor->id == id) factory = &f;
    }
    if (factory == nullptr) throw std::invalid_argument("'" + item + "': " + id + " is not served");
    builds.emplace_back(factory, level_config(*factory->descriptor, *level));
  }
  return builds;
}

}  // namespace clearsky::server
