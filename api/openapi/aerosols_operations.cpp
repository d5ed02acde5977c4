// The aerosol inversion operations (openapi_area.h): users' AERONET phase-function inversions
// for the measured_aerosols model (api/aerosols/aerosols_api.h; docs/data-api.md "Aerosol
// inversions").
#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {
namespace {

Json schemas() {
  return parse(R"json({
  "AerosolInversionFile": {
    "type": "string",
    "format": "binary",
    "description": "An AERONET almucantar inversion of phase functions (.pfn, version 2 layout: four header lines, then one retrieval per line), of one day, at most 1 MiB."
  },
  "AerosolRetrieval": {
    "type": "object",
    "required": ["date", "time_utc", "time_utc_h", "aod_440", "angstrom_440_870", "aod"],
    "additionalProperties": false,
    "properties": {
      "date": {"type": "string", "description": "As written, dd:mm:yyyy."},
      "time_utc": {"type": "string", "description": "As written, hh:mm:ss UTC."},
      "time_utc_h": {"type": "number", "description": "Hours since midnight UTC (what retrieval_time_utc_h selects by)."},
      "aod_440": {"type": "number", "description": "tau440(measured)."},
      "angstrom_440_870": {"type": "number", "description": "alpha440-870."},
      "aod": {"type": "array", "items": {"type": "number"}, "description": "Aerosol optical depth at each of wavelengths_nm (Angstrom law through aod_440)."}
    }
  },
  "AerosolInversion": {
    "type": "object",
    "description": "A stored inversion. GET /v1/aerosols/{id} and POST add level, wavelengths_nm, angle_count and retrievals.",
    "required": ["id", "name", "content_hash", "site", "latitude_deg", "longitude_deg", "first_day", "last_day", "retrieval_count", "size_bytes", "created_utc", "location"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1, "description": "What aerosols= selects; never reused."},
      "name": {"type": "string"},
      "content_hash": {"type": "string", "description": "FNV-1a 64 of the file, 16 hex digits: the key of the model's cached tables."},
      "site": {"type": "string"},
      "latitude_deg": {"type": "number"},
      "longitude_deg": {"type": "number"},
      "first_day": {"type": "string", "description": "yyyy-mm-dd of the first retrieval."},
      "last_day": {"type": "string", "description": "yyyy-mm-dd of the last retrieval."},
      "retrieval_count": {"type": "integer", "minimum": 1},
      "size_bytes": {"type": "integer"},
      "created_utc": {"type": "string"},
      "location": {"type": "string"},
      "level": {"type": "string", "description": "The file's level line."},
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}},
      "angle_count": {"type": "integer", "description": "Scattering angles per phase function."},
      "retrievals": {"type": "array", "items": {"$ref": "#/components/schemas/AerosolRetrieval"}}
    }
  },
  "AerosolInversionList": {"type": "array", "items": {"$ref": "#/components/schemas/AerosolInversion"}}
})json");
}

Json operations() {
  return parse(R"json({
  "listAerosols": {
    "operationId": "listAerosols",
    "tags": ["aerosols"],
    "summary": "Stored aerosol inversions",
    "description": "The uploaded AERONET inversions, newest first, without their retrievals.",
    "parameters": [
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The inversions.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/AerosolInversionList"}}}
      },
      "400": {"description": "An unknown parameter, an invalid limit or cursor."}
    }
  },
  "uploadAerosols": {
    "operationId": "uploadAerosols",
    "tags": ["aerosols"],
    "summary": "Upload an AERONET inversion",
    "description": "Stores an AERONET phase-function inversion file (the body) for the measured_aerosols model, after reading it whole: 201 with the stored inversion; its id is what aerosols= selects on the sky endpoints and in evaluation and fit parameters.",
    "parameters": [
      {"name": "name", "in": "query", "required": true, "description": "A label, 1 to 100 bytes without control characters.", "schema": {"type": "string"}, "example": "egbert-2013-05-27"}
    ],
    "requestBody": {
      "required": true,
      "description": "The .pfn file.",
      "content": {
        "text/plain": {"schema": {"$ref": "#/components/schemas/AerosolInversionFile"}},
        "text/csv": {"schema": {"$ref": "#/components/schemas/AerosolInversionFile"}},
        "application/octet-stream": {"schema": {"$ref": "#/components/schemas/AerosolInversionFile"}}
      }
    },
    "responses": {
      "201": {
        "description": "Stored: the inversion with its retrievals.",
        "headers": {"Location": {"description": "/v1/aerosols/{id}", "required": true, "schema": {"type": "string"}}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/AerosolInversion"}}}
      },
      "400": {"description": "No name or an invalid one, an unknown parameter, no body, or a body the AERONET reader refuses (code invalid_inversion, parameter body; the message names the line and column)."},
      "413": {"description": "A body above 1 MiB (parameter body)."},
      "415": {"description": "A Content-Type other than text/plain, text/csv or application/octet-stream."}
    }
  },
  "getAerosols": {
    "operationId": "getAerosols",
    "tags": ["aerosols"],
    "summary": "One aerosol inversion",
    "description": "A stored inversion: site, days, wavelengths, and every retrieval with its time and aerosol optical depth per wavelength.",
    "parameters": [
      {"name": "id", "in": "path", "required": true, "description": "The inversion's id.", "schema": {"type": "integer", "minimum": 1}, "example": 1}
    ],
    "responses": {
      "200": {
        "description": "The inversion.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/AerosolInversion"}}}
      },
      "400": {"description": "An unknown parameter or an id that is not a positive integer."},
      "404": {"description": "No such inversion (code unknown_aerosols)."}
    }
  }
})json");
}

}  // namespace

Area aerosols_area() {
  Area area;
  area.components["schemas"] = schemas();
  area.operations = operations();
  complete_errors(area.operations);
  for (auto& [id, operation] : area.operations.items()) {
    operation["security"] = Json::array();
    if (id == "uploadAerosols") make_write(operation);
    add_common_errors(operation, id == "uploadAerosols");
    add_query_replica_answer(operation);
  }
  return area;
}

}  // namespace clearsky::api::openapi
