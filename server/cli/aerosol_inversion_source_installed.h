// measured_aerosols' aerosols=ID reads the aerosol_inversions table of the command's database
// (models/measured_aerosols/aerosol_inversion_source.h; docs/data-api.md "Using an inversion"):
// installed by the commands that have one (serve as a writer, evaluate, fit) for their lifetime,
// one connection per lookup, removed when the command ends. Without it every id but 0 is unknown.
#pragma once

#include <cstdint>
#include <string>

#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "storage/repositories/aerosol_inversion_repository.h"

namespace clearsky::cli {

class AerosolInversionSourceInstalled {
 public:
  explicit AerosolInversionSourceInstalled(const std::string& db_path) {
    install_aerosol_inversion_source([db_path](std::int64_t id) {
      storage::Database db = storage::Database::open(db_path);
      return storage::AerosolInversionRepository(db).content(id);
    });
  }
  ~AerosolInversionSourceInstalled() { install_aerosol_inversion_source({}); }
  AerosolInversionSourceInstalled(const AerosolInversionSourceInstalled&) = delete;
  AerosolInversionSourceInstalled& operator=(const AerosolInversionSourceInstalled&) = delete;
};

}  // namespace clearsky::cli
