// Test helper: a zip (libarchive) of one capture in the Kider et al. 2014 layout
// (storage/importers/kider_format.h): the 81 files DATE___HH.MM.SS_-_INDEX____AZIMUTH___
// ELEVATION.asd.rad.txt, each a header line and a flat spectrum over 350..2500 nm every 1 nm,
// for tests of archive imports that need no shared data.
#pragma once

#include <archive.h>
#include <archive_entry.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace clearsky::testing {

// label: "2013-05-27___12.00.00" (the local time of the site).
inline void write_synthetic_kider_zip(const std::filesystem::path& path,
                                      const std::string& label = "2013-05-27___12.00.00") {
  std::string spectrum = "Wavelength\tradiance\n";
  for (int nm = 350; nm <= 2500; ++nm) spectrum += std::to_string(nm) + "\t0.05\n";
  archive* writer = archive_write_new();
  archive_write_set_format_zip(writer);
  if (archive_write_open_filename(writer, path.c_str()) != ARCHIVE_OK) {
    archive_write_free(writer);
    throw std::runtime_error("cannot write " + path.string());
  }
  for (int index = 0; index < 81; ++index) {
    std::string name = label;
    name += "_-_";
    name += std::to_string(index);
    name += "____";
    name += std::to_string(index * 4);
    name += ".0___";
    name += std::to_string(10 + index);
    name += ".0.asd.rad.txt";
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, name.c_str());
    archive_entry_set_size(entry, static_cast<la_int64_t>(spectrum.size()));
    archive_entry_set_filetype(entry, AE_IFREG);
    archive_entry_set_perm(entry, 0644);
    const bool written = archive_write_header(writer, entry) == ARCHIVE_OK &&
                         archive_write_data(writer, spectrum.data(), spectrum.size()) ==
                             static_cast<la_ssize_t>(spectrum.size());
    archive_entry_free(entry);
    if (!written) {
      archive_write_free(writer);
      throw std::runtime_error("cannot write " + path.string());
    }
  }
  archive_write_close(writer);
  archive_write_free(writer);
}

}  // namespace clearsky::testing
