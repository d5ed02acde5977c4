// The dataset and import operations (openapi_area.h): stored measurement datasets and the
// background imports that fill them (api/datasets/datasets_api.h, api/imports/imports_api.h,
// server/http/data_routes.cpp). The examples are answers of a server that imported a synthetic
// capture in the Kider et al. 2014 format (tests/server/openapi/synthetic_kider.py).
#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {
namespace {

Json schemas() {
  return parse(R"json({
  "DatasetSummary": {
    "type": "object",
    "required": ["name", "format", "kind", "created", "captures", "samples", "irradiance_samples"],
    "additionalProperties": false,
    "properties": {
      "name": {"type": "string"},
      "format": {"type": "string", "description": "The measurement format: kider2014 (Kider et al. 2014 archives), sky-radiance (the open format), irradiance (the open broadband irradiance format) or kider-pyranometer (docs/measurement-formats.md)."},
      "kind": {"$ref": "#/components/schemas/DatasetKind"},
      "created": {"type": "string", "format": "date-time"},
      "captures": {"type": "integer", "minimum": 0},
      "samples": {"type": "integer", "minimum": 0},
      "irradiance_samples": {"type": "integer", "minimum": 0, "description": "The instants of a broadband_irradiance dataset."}
    }
  },
  "DatasetKind": {
    "type": "string",
    "enum": ["sky_radiance", "broadband_irradiance"],
    "description": "sky_radiance: captures of spectral sky radiance; broadband_irradiance: a time series of measured GHI, DHI and DNI (docs/data-api.md \"Dataset kinds\")."
  },
  "IrradianceSample": {
    "type": "object",
    "required": ["time", "time_utc", "place", "ghi", "dhi", "dni", "averaging_s"],
    "additionalProperties": false,
    "properties": {
      "time": {"type": "string", "format": "date-time", "description": "In the UTC offset of the instrument's clock."},
      "time_utc": {"type": "string", "format": "date-time"},
      "place": {"$ref": "#/components/schemas/Place"},
      "ghi": {"type": "number", "nullable": true, "description": "Global horizontal irradiance, W/m2; null when not measured."},
      "dhi": {"type": "number", "nullable": true, "description": "Diffuse horizontal irradiance, W/m2."},
      "dni": {"type": "number", "nullable": true, "description": "Direct normal irradiance, W/m2."},
      "averaging_s": {"type": "number", "nullable": true, "description": "The period the values average, s, when known."}
    }
  },
  "DatasetList": {
    "type": "array",
    "items": {"$ref": "#/components/schemas/DatasetSummary"}
  },
  "Place": {
    "type": "object",
    "required": ["latitude", "longitude", "elevation_m"],
    "additionalProperties": false,
    "properties": {
      "latitude": {"type": "number", "minimum": -90, "maximum": 90},
      "longitude": {"type": "number", "minimum": -180, "maximum": 180},
      "elevation_m": {"type": "number"}
    }
  },
  "CaptureSample": {
    "type": "object",
    "description": "One measured direction; with capture=LABEL also its spectrum.",
    "required": ["index", "view_zenith", "view_azimuth", "flags"],
    "additionalProperties": false,
    "properties": {
      "index": {"type": "integer", "minimum": 0},
      "view_zenith": {"type": "number", "description": "Degrees."},
      "view_azimuth": {"type": "number", "description": "Degrees clockwise from North."},
      "flags": {"type": "integer", "description": "Quality flags (1: the sample is known to be defective, kept as measured)."},
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}},
      "radiance": {"type": "array", "items": {"type": "number"}, "description": "W/(m2.sr.nm), as measured."}
    }
  },
  "Capture": {
    "type": "object",
    "required": ["label", "time", "time_utc", "place", "sun_zenith", "sun_azimuth", "sun_azimuth_estimated", "samples"],
    "additionalProperties": false,
    "properties": {
      "label": {"type": "string"},
      "time": {"type": "string", "format": "date-time", "description": "In the site's UTC offset."},
      "time_utc": {"type": "string", "format": "date-time"},
      "place": {"$ref": "#/components/schemas/Place"},
      "sun_zenith": {"type": "number", "nullable": true, "description": "Computed by SPA without refraction, degrees."},
      "sun_azimuth": {"type": "number", "nullable": true},
      "sun_azimuth_estimated": {"type": "number", "nullable": true},
      "samples": {
        "description": "The number of samples; with samples=true or capture=LABEL the samples themselves.",
        "oneOf": [
          {"type": "integer", "minimum": 0},
          {"type": "array", "items": {"$ref": "#/components/schemas/CaptureSample"}}
        ]
      }
    }
  },
  "Dataset": {
    "type": "object",
    "required": ["name", "format", "kind", "created", "captures"],
    "additionalProperties": false,
    "properties": {
      "name": {"type": "string"},
      "format": {"type": "string"},
      "kind": {"$ref": "#/components/schemas/DatasetKind"},
      "created": {"type": "string", "format": "date-time"},
      "captures": {"type": "array", "items": {"$ref": "#/components/schemas/Capture"}, "description": "Empty for a broadband_irradiance dataset."},
      "irradiance": {"type": "array", "items": {"$ref": "#/components/schemas/IrradianceSample"}, "description": "A broadband_irradiance dataset's series, by instant."}
    }
  },
  "DatasetDeleted": {
    "type": "object",
    "required": ["deleted"],
    "additionalProperties": false,
    "properties": {"deleted": {"type": "string", "description": "The dataset's name."}}
  },
  "ImportReport": {
    "description": "What an import added: captures for the sky radiance formats and Kider archives (kind sky_radiance), samples for the broadband irradiance formats (kind broadband_irradiance).",
    "oneOf": [
      {"$ref": "#/components/schemas/CaptureImportReport"},
      {"$ref": "#/components/schemas/IrradianceImportReport"}
    ],
    "discriminator": {
      "propertyName": "kind",
      "mapping": {
        "sky_radiance": "#/components/schemas/CaptureImportReport",
        "broadband_irradiance": "#/components/schemas/IrradianceImportReport"
      }
    }
  },
  "CaptureImportReport": {
    "type": "object",
    "description": "The import of captures of spectral sky radiance (Kider archives, sky-radiance-csv, sky-radiance-json).",
    "required": ["dataset", "kind", "added", "unchanged", "samples_added", "seconds"],
    "additionalProperties": false,
    "properties": {
      "dataset": {"type": "string"},
      "kind": {"type": "string", "enum": ["sky_radiance"]},
      "added": {"type": "array", "items": {"type": "string"}, "description": "Capture labels added."},
      "unchanged": {"type": "array", "items": {"type": "string"}, "description": "Capture labels already stored with the same content."},
      "samples_added": {"type": "integer", "minimum": 0},
      "seconds": {"type": "number", "minimum": 0}
    }
  },
  "IrradianceImportReport": {
    "type": "object",
    "description": "The import of a broadband irradiance series (irradiance-csv, irradiance-json).",
    "required": ["dataset", "kind", "samples_added", "samples_unchanged", "seconds"],
    "additionalProperties": false,
    "properties": {
      "dataset": {"type": "string"},
      "kind": {"type": "string", "enum": ["broadband_irradiance"]},
      "samples_added": {"type": "integer", "minimum": 0},
      "samples_unchanged": {"type": "integer", "minimum": 0, "description": "Samples identical to one the dataset holds."},
      "first_time": {"type": "string", "format": "date-time", "description": "Of the earliest sample; absent without samples."},
      "last_time": {"type": "string", "format": "date-time", "description": "Of the latest sample; absent without samples."},
      "seconds": {"type": "number", "minimum": 0}
    }
  },
  "ImportProgress": {
    "type": "object",
    "nullable": true,
    "required": ["phase", "bytes_read", "bytes_total", "entries_read", "entries_total", "files_read", "captures_added", "samples_added"],
    "additionalProperties": false,
    "properties": {
      "phase": {"type": "string", "enum": ["reading", "writing", "committed"]},
      "bytes_read": {"type": "integer", "minimum": 0},
      "bytes_total": {"type": "integer", "minimum": 0, "nullable": true, "description": "Of the archive as stored; null while unknown."},
      "entries_read": {"type": "integer", "minimum": 0},
      "entries_total": {"type": "integer", "minimum": 0, "nullable": true, "description": "Known for folders, for archives at their end."},
      "files_read": {"type": "integer", "minimum": 0},
      "captures_added": {"type": "integer", "minimum": 0},
      "samples_added": {"type": "integer", "minimum": 0}
    }
  },
  "ImportError": {
    "type": "object",
    "description": "Why an import failed (null unless it did).",
    "nullable": true,
    "required": ["code", "message"],
    "additionalProperties": false,
    "properties": {
      "code": {"type": "string", "description": "invalid_archive, conflict, too_large (the message names max_entry_bytes or max_import_bytes), insufficient_storage (the disk is full), interrupted (the server stopped), cancelled (dropped at a graceful stop), ..."},
      "message": {"type": "string"}
    }
  },
  "Import": {
    "type": "object",
    "required": ["id", "dataset", "format", "source", "path", "upload_bytes", "status", "progress", "timings", "report", "error", "location"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "dataset": {"type": "string"},
      "format": {"type": "string", "enum": ["kider", "sky-radiance-csv", "sky-radiance-json", "irradiance-csv", "irradiance-json"]},
      "source": {"type": "string", "enum": ["upload", "path"]},
      "path": {"type": "string", "nullable": true, "description": "With source=path."},
      "upload_bytes": {"type": "integer", "nullable": true, "description": "With source=upload."},
      "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed"]},
      "progress": {"$ref": "#/components/schemas/ImportProgress"},
      "timings": {
        "type": "object",
        "required": ["created", "started", "finished"],
        "additionalProperties": false,
        "properties": {
          "created": {"type": "string", "format": "date-time"},
          "started": {"type": "string", "format": "date-time", "nullable": true},
          "finished": {"type": "string", "format": "date-time", "nullable": true}
        }
      },
      "report": {
        "type": "object",
        "nullable": true,
        "description": "What the import added; null until it succeeds.",
        "allOf": [{"$ref": "#/components/schemas/ImportReport"}]
      },
      "error": {"$ref": "#/components/schemas/ImportError"},
      "location": {"type": "string", "description": "/v1/imports/{id}"}
    }
  },
  "ImportList": {
    "type": "array",
    "items": {"$ref": "#/components/schemas/Import"}
  },
  "ArchiveUpload": {
    "type": "string",
    "format": "binary",
    "description": "A .7z, zip or tar archive of Kider .asd.rad.txt files, or of the published .7z captures."
  },
  "SkyRadianceCsv": {
    "type": "string",
    "description": "The open sky-radiance format as CSV (docs/measurement-formats.md): a header naming the columns time, latitude, longitude, elevation_m, view_zenith, view_azimuth, wavelength_nm, radiance (any order), then one row per measured value: time ISO 8601 with a UTC offset or Z; latitude and longitude in degrees (North and East positive); elevation_m in m; view_zenith in degrees from the vertical; view_azimuth in degrees clockwise from North; wavelength_nm; radiance in W/(m2.sr.nm). Rows of one instant are one capture, rows of one view direction in it one spectrum.",
    "example": "time,latitude,longitude,elevation_m,view_zenith,view_azimuth,wavelength_nm,radiance\n2024-06-21T10:00:00+02:00,48.8566,2.3522,35,20,0,360,0.128637\n"
  },
  "SkyRadianceJson": {
    "type": "object",
    "description": "The open sky-radiance format as JSON (docs/measurement-formats.md): the file's site, or each sample's own (not both); the members of a sample as the CSV's columns.",
    "required": ["samples"],
    "additionalProperties": false,
    "properties": {
      "site": {"$ref": "#/components/schemas/Place"},
      "samples": {
        "type": "array",
        "items": {
          "type": "object",
          "required": ["time", "view_zenith", "view_azimuth", "wavelength_nm", "radiance"],
          "additionalProperties": false,
          "properties": {
            "time": {"type": "string", "format": "date-time", "description": "ISO 8601 with a UTC offset or Z."},
            "latitude": {"type": "number", "minimum": -90, "maximum": 90},
            "longitude": {"type": "number", "minimum": -180, "maximum": 180},
            "elevation_m": {"type": "number", "minimum": -500, "maximum": 9000},
            "view_zenith": {"type": "number", "minimum": 0, "maximum": 180, "description": "Degrees from the local vertical."},
            "view_azimuth": {"type": "number", "minimum": 0, "exclusiveMaximum": true, "maximum": 360, "description": "Degrees clockwise from North."},
            "wavelength_nm": {"type": "number", "exclusiveMinimum": true, "minimum": 0, "maximum": 1000000},
            "radiance": {"type": "number", "minimum": 0, "description": "W/(m2.sr.nm)."}
          }
        }
      }
    }
  }
})json");
}

const char* kImportExample =
    R"json({"id": 1, "dataset": "synthetic", "format": "kider", "source": "path", "path": "/tmp/oa/synth", "upload_bytes": null, "status": "succeeded", "progress": {"phase": "committed", "bytes_read": 4830932, "bytes_total": 4830932, "entries_read": 81, "entries_total": 81, "files_read": 81, "captures_added": 1, "samples_added": 81}, "timings": {"created": "2026-11-23T19:42:13.347Z", "started": "2026-11-23T19:42:13.348Z", "finished": "2026-11-23T19:42:13.562Z"}, "report": {"dataset": "synthetic", "kind": "sky_radiance", "added": ["2013-05-27___11.45.00"], "unchanged": [], "samples_added": 81, "seconds": 0.214297728}, "error": null, "location": "/v1/imports/1"})json";

Json operations() {
  Json ops = parse(R"json({
  "listDatasets": {
    "operationId": "listDatasets",
    "tags": ["datasets"],
    "summary": "Stored datasets",
    "description": "The stored measurement datasets with their capture and sample counts.",
    "parameters": [
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The datasets.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/DatasetList"},
          "example": [{"name": "synthetic", "format": "kider2014", "kind": "sky_radiance", "created": "2026-11-23T19:42:13.533Z", "captures": 1, "samples": 81, "irradiance_samples": 0}]
        }}
      },
      "400": {"description": "An unknown or invalid parameter."}
    }
  },
  "importDataset": {
    "operationId": "importDataset",
    "tags": ["datasets", "imports"],
    "summary": "Import captures into a dataset",
    "description": "Imports measured skies as a background job (docs/measurement-formats.md): Kider et al. 2014 captures, or a file of the open sky-radiance format (CSV or JSON: format=, or the body's media type text/csv or application/json). An upload is checked whole before it is accepted: the open format's every value (400 invalid_body naming the column or member, the message giving the row), an archive's format (400 invalid_archive naming body). For Kider archives, the body is an archive (streamed to disk under --max-upload-bytes, default 1 GiB), or no body and path= names an archive or folder under one of the server's import roots (--import-root; none by default). The route checks the parameters, name, format and path, then answers 202 with the import's state; follow Location. The import reads at most --max-entry-bytes (default 16 MiB) from one archive entry or file and --max-import-bytes (default 256 MiB) in all, counted as it reads: beyond, it fails with code too_large naming the limit. The import is one transaction: a failure leaves nothing behind.",
    "parameters": [
      {"name": "name", "in": "query", "required": true, "description": "The dataset to import into (created when absent): 1 to 128 characters of A-Z a-z 0-9 . _ -, the first a letter or a digit.", "schema": {"type": "string", "pattern": "^[A-Za-z0-9][A-Za-z0-9._-]{0,127}$"}, "example": "synthetic"},
      {"name": "format", "in": "query", "required": false, "description": "The measurement format; absent: from the body's media type (text/csv: sky-radiance-csv, application/json: sky-radiance-json), else kider. The broadband irradiance formats (irradiance-csv, irradiance-json) are named here, with text/csv, application/json or no media type.", "schema": {"type": "string", "enum": ["kider", "sky-radiance-csv", "sky-radiance-json", "irradiance-csv", "irradiance-json"]}},
      {"name": "lat", "in": "query", "required": false, "description": "kider only: the site's latitude, North positive, decimal or DMS (default 42.443449, Cornell).", "schema": {"type": "string"}, "example": "42.443449"},
      {"name": "lon", "in": "query", "required": false, "description": "kider only: the site's longitude, East positive (default -76.481962).", "schema": {"type": "string"}, "example": "-76.481962"},
      {"name": "elevation", "in": "query", "required": false, "description": "kider only: the site's elevation above sea level, m (default 250).", "schema": {"type": "number", "minimum": -500, "maximum": 9000}},
      {"name": "utc_offset", "in": "query", "required": false, "description": "kider only: the UTC offset of the file names' local time, Z, +hh:mm, +hhmm or +hh, at most 14 hours (default -04:00).", "schema": {"type": "string"}, "example": "-04:00"},
      {"name": "path", "in": "query", "required": false, "description": "An archive or folder on the server, instead of a body: relative to an import root (tried in turn), or absolute inside one; links may not lead out of the root.", "schema": {"type": "string"}}
    ],
    "requestBody": {
      "required": false,
      "description": "The archive; absent (Content-Length: 0) with path=.",
      "content": {
        "application/octet-stream": {"schema": {"$ref": "#/components/schemas/ArchiveUpload"}},
        "text/csv": {"schema": {"$ref": "#/components/schemas/SkyRadianceCsv"}},
        "application/json": {"schema": {"$ref": "#/components/schemas/SkyRadianceJson"}}
      }
    },
    "responses": {
      "202": {
        "description": "Queued: the import's state (as GET /v1/imports/{id}).",
        "headers": {"Location": {"description": "/v1/imports/{id}", "required": true, "schema": {"type": "string"}}},
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Import"},
          "example": {"id": 1, "dataset": "synthetic", "format": "kider", "source": "path", "path": "/tmp/oa/synth", "upload_bytes": null, "status": "running", "progress": {"phase": "reading", "bytes_read": 1073533, "bytes_total": 4830932, "entries_read": 18, "entries_total": 81, "files_read": 18, "captures_added": 0, "samples_added": 0}, "timings": {"created": "2026-11-23T19:42:13.347Z", "started": "2026-11-23T19:42:13.348Z", "finished": null}, "report": null, "error": null, "location": "/v1/imports/1"}
        }}
      },
      "400": {"description": "A missing or unknown parameter, a dataset name outside the rule (parameter name), an unknown format, no body and no path, or a body and a path; a site or clock parameter or path= with the open format; an upload of the open format with malformed content (code invalid_body naming the column or member, the message giving the row); a body sent as a Kider archive that is no archive (code invalid_archive, parameter body)."},
      "415": {"description": "The body's media type is none of an import's, or contradicts format= (code unsupported_media_type, parameter Content-Type)."},
      "404": {"description": "path= names nothing that can be imported (code path_not_importable, parameter path): the same answer whether the path is missing, outside the import roots, leads out of them through a link or is a device, fifo or socket."},
      "413": {"description": "The upload is above --max-upload-bytes (code too_large, parameter body), or a file of the open format above --max-entry-bytes (parameter max_entry_bytes)."},
      "507": {"description": "The server's disk is full: the upload cannot be spooled or the import cannot be recorded (code insufficient_storage, parameter disk)."},
      "503": {"description": "Too many imports are queued (--import-queue; code busy), or the server runs no import workers."}
    }
  },
  "getDataset": {
    "operationId": "getDataset",
    "tags": ["datasets"],
    "summary": "One dataset",
    "description": "A dataset's captures: time, place and the sun's angles; samples=true adds each capture's sample directions, capture=LABEL keeps one capture and adds each sample's spectrum.",
    "parameters": [
      {"name": "name", "in": "path", "required": true, "description": "The dataset's name.", "schema": {"type": "string"}, "example": "synthetic"},
      {"name": "samples", "in": "query", "required": false, "description": "Add each capture's samples (true/false or 1/0).", "schema": {"type": "boolean", "default": false}},
      {"name": "capture", "in": "query", "required": false, "description": "Only the capture with this label, with each sample's spectrum.", "schema": {"type": "string"}, "example": "2013-05-27___11.45.00"}
    ],
    "responses": {
      "200": {
        "description": "The dataset.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Dataset"},
          "example": {"name": "synthetic", "format": "kider2014", "kind": "sky_radiance", "created": "2026-11-23T19:42:13.533Z", "captures": [{"label": "2013-05-27___11.45.00", "time": "2013-05-27T11:45:00-04:00", "time_utc": "2013-05-27T15:45:00Z", "place": {"latitude": 42.443449, "longitude": -76.481962, "elevation_m": 250.0}, "sun_zenith": 26.651259213110777, "sun_azimuth": 136.07696990085265, "sun_azimuth_estimated": null, "samples": 81}]}
        }}
      },
      "400": {"description": "An unknown parameter or a samples value other than true or false."},
      "404": {"description": "No such dataset (code unknown_dataset), or no capture of that label (unknown_capture)."}
    }
  },
  "deleteDataset": {
    "operationId": "deleteDataset",
    "tags": ["datasets"],
    "summary": "Delete a dataset",
    "description": "Deletes a dataset with its captures and their evaluation runs.",
    "parameters": [
      {"name": "name", "in": "path", "required": true, "description": "The dataset's name.", "schema": {"type": "string"}, "example": "synthetic"}
    ],
    "responses": {
      "200": {
        "description": "Deleted.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/DatasetDeleted"},
          "example": {"deleted": "synthetic"}
        }}
      },
      "400": {"description": "A query parameter (the route takes none)."},
      "404": {"description": "No such dataset (code unknown_dataset)."}
    }
  },
  "listImports": {
    "operationId": "listImports",
    "tags": ["imports"],
    "summary": "Dataset imports",
    "description": "Imports, newest first, with their state, progress (live while running), timings, and report or error.",
    "parameters": [
      {"name": "status", "in": "query", "required": false, "description": "Only imports in this state.", "schema": {"type": "string", "enum": ["queued", "running", "succeeded", "failed"]}},
      {"name": "dataset", "in": "query", "required": false, "description": "Only imports into this dataset.", "schema": {"type": "string"}},
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The imports.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ImportList"}}}
      },
      "400": {"description": "An unknown parameter or an invalid status."}
    }
  },
  "getImport": {
    "operationId": "getImport",
    "tags": ["imports"],
    "summary": "One import",
    "description": "An import's state; an import a crash interrupted reads failed with code interrupted.",
    "parameters": [
      {"name": "id", "in": "path", "required": true, "description": "The import's id.", "schema": {"type": "integer", "minimum": 1}, "example": 1}
    ],
    "responses": {
      "200": {
        "description": "The import.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Import"}}}
      },
      "400": {"description": "An id that is not a positive integer, or a query parameter."},
      "404": {"description": "No such import (code unknown_import)."}
    }
  }
})json");
  ops["listImports"]["responses"]["200"]["content"]["application/json"]["example"] =
      Json::array({parse(kImportExample)});
  ops["getImport"]["responses"]["200"]["content"]["application/json"]["example"] =
      parse(kImportExample);
  return ops;
}

}  // namespace

// Turns each error response's description into a response with the Error body.
void complete_errors(Json& operations) {
  for (auto& [id, operation] : operations.items()) {
    for (auto& [status, response] : operation["responses"].items()) {
      if (status[0] != '4' && status[0] != '5') continue;
      if (response.contains("$ref") || response.contains("content")) continue;
      const std::string description = response["description"];
      response = status == "503" ? retry_later_response(description) : error_response(description);
    }
  }
}

Area datasets_area() {
  Area area;
  area.components["schemas"] = schemas();
  area.operations = operations();
  complete_errors(area.operations);
  for (auto& [id, operation] : area.operations.items()) {
    operation["security"] = Json::array();
    if (id == "importDataset" || id == "deleteDataset") make_write(operation);
    if (id == "importDataset")
      operation["responses"]["403"] = error_response(
          "Writes are disabled (no token; code writes_disabled), or path= was given and the "
          "server has no import roots (--import-root; code path_imports_disabled).");
    add_common_errors(operation, id == "importDataset");
    add_query_replica_answer(operation);
  }
  return area;
}

}  // namespace clearsky::api::openapi
