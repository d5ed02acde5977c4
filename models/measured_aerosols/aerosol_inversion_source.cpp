// The process-wide source of uploaded inversions.
#include "models/measured_aerosols/aerosol_inversion_source.h"

#include <memory>
#include <mutex>

namespace clearsky {

namespace {

std::mutex& source_mutex() {
  static std::mutex m;
  return m;
}

std::shared_ptr<const AerosolInversionSource>& installed_source() {
  static std::shared_ptr<const AerosolInversionSource> source;
  return source;
}

}  // namespace

void install_aerosol_inversion_source(AerosolInversionSource source) {
  auto next = source ? std::make_shared<const AerosolInversionSource>(std::move(source)) : nullptr;
  const std::lock_guard lock(source_mutex());
  installed_source() = std::move(next);
}

std::optional<std::string> aerosol_inversion_bytes(std::int64_t id) {
  std::shared_ptr<const AerosolInversionSource> source;
  {
    const std::lock_guard lock(source_mutex());
    source = installed_source();
  }
  if (!source) return std::nullopt;
  return (*source)(id);
}

}  // namespace clearsky
