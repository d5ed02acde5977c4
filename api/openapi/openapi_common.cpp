// The components every area shares (openapi_area.h): the error body, the responses and headers
// of the HTTP layer (server/README.md "Behaviour decided here"), pagination and caching.
#include <stdexcept>

#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {

Json parse(const char* text) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw std::logic_error(std::string("OpenAPI content does not parse: ") + e.what());
  }
}

Json ref(const std::string& kind, const std::string& name) {
  return {{"$ref", "#/components/" + kind + "/" + name}};
}

Json json_response(const std::string& description, const std::string& schema, const Json& example) {
  Json media = {{"schema", ref("schemas", schema)}};
  if (!example.is_null()) media["example"] = example;
  return {{"description", description}, {"content", {{"application/json", media}}}};
}

Json error_response(const std::string& description) { return json_response(description, "Error"); }

Json retry_later_response(const std::string& description) {
  Json response = error_response(description);
  response["headers"] = {{"Retry-After", ref("headers", "Retry-After")}};
  return response;
}

void add_common_errors(Json& operation, bool takes_body) {
  Json& responses = operation["responses"];
  if (!responses.contains("413")) {
    responses["413"] =
        takes_body ? ref("responses", "PayloadTooLarge") : ref("responses", "UnexpectedBody");
  }
  responses["500"] = ref("responses", "InternalError");
}

void add_query_replica_answer(Json& operation) {
  constexpr const char* kReplica =
      "On a query replica (serve --role query), which has no database: code no_database, "
      "parameter role.";
  Json& responses = operation["responses"];
  if (!responses.contains("404")) {
    responses["404"] = error_response(kReplica);
    return;
  }
  Json& description = responses["404"]["description"];
  description = description.get<std::string>() + " " + kReplica;
}

void add_revalidation(Json& operation) {
  if (!operation.contains("parameters")) operation["parameters"] = Json::array();
  operation["parameters"].push_back(ref("parameters", "If-None-Match"));
  Json& headers = operation["responses"]["200"]["headers"];
  headers["ETag"] = ref("headers", "ETag");
  headers["Cache-Control"] = ref("headers", "Cache-Control");
  operation["responses"]["304"] = ref("responses", "NotModified");
}

void make_write(Json& operation) {
  operation["security"] = Json::array({{{"bearer", Json::array()}}});
  operation["responses"]["401"] = ref("responses", "Unauthorized");
  operation["responses"]["403"] = ref("responses", "WritesDisabled");
}

Json common_components() {
  return parse(R"json({
  "schemas": {
    "Error": {
      "type": "object",
      "description": "Every refusal: a stable machine-readable code, a message for people and the request parameter at fault (null when none is).",
      "required": ["error"],
      "additionalProperties": false,
      "properties": {
        "error": {"$ref": "#/components/schemas/ErrorDetail"}
      },
      "example": {"error": {"code": "unknown_model", "message": "model: no model 'nope' (available: preetham, hosek)", "parameter": "model"}}
    },
    "ErrorDetail": {
      "type": "object",
      "required": ["code", "message", "parameter"],
      "additionalProperties": false,
      "properties": {
        "code": {
          "type": "string",
          "description": "e.g. invalid_parameter, unknown_parameter, missing_parameter, conflicting_parameters, invalid_body, unknown_model, unknown_dataset, unknown_fit, unknown_aerosols (404: no such stored aerosol inversion, also for aerosols= of measured_aerosols), fit_not_succeeded (409), fit_model_mismatch (409), not_found, method_not_allowed (405, with an Allow header, for a method a path does not serve), too_large, model_cannot_answer, model_not_ready, busy, unauthorized, writes_disabled, no_database (404 on a query replica, serve --role query: parameter role), draining (/readyz of a stopping server), path_imports_disabled, path_not_importable, insufficient_storage (507), internal_error"
        },
        "message": {"type": "string"},
        "parameter": {
          "type": "string",
          "nullable": true,
          "description": "The query parameter, body member (views[3]), path segment or header at fault; null when the error is about no single parameter."
        }
      }
    }
  },
  "responses": {
    "Unauthorized": {
      "description": "The Authorization header is missing or its bearer token is not the server's (code unauthorized).",
      "headers": {"WWW-Authenticate": {"$ref": "#/components/headers/WWW-Authenticate"}},
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/Error"},
        "example": {"error": {"code": "unauthorized", "message": "this request needs the header Authorization: Bearer TOKEN", "parameter": null}}
      }}
    },
    "WritesDisabled": {
      "description": "The server runs without a token (--token or CLEARSKY_TOKEN), so every write is refused (code writes_disabled); reads stay open.",
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/Error"},
        "example": {"error": {"code": "writes_disabled", "message": "writes are disabled: the server has no token (--token or CLEARSKY_TOKEN)", "parameter": null}}
      }}
    },
    "PayloadTooLarge": {
      "description": "The request body is above the payload limit (--payload-max-bytes, default 8 MiB), or a parameter is above a configured limit (views, wavelengths, image size); code too_large, parameter naming it.",
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/Error"},
        "example": {"error": {"code": "too_large", "message": "body: the request body is above the limit of 8388608 bytes", "parameter": "body"}}
      }}
    },
    "UnexpectedBody": {
      "description": "This route takes no body: a body above the payload limit (--payload-max-bytes), or a chunked one, is refused before it is read and the connection is closed (code too_large, parameter body).",
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/Error"},
        "example": {"error": {"code": "too_large", "message": "body: the request body is above the limit of 8388608 bytes", "parameter": "body"}}
      }}
    },
    "InternalError": {
      "description": "An internal error (code internal_error, or numerical_failure when a model's computation failed); the details are in the server's log only.",
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/Error"},
        "example": {"error": {"code": "internal_error", "message": "internal error", "parameter": null}}
      }}
    },
    "NotModified": {
      "description": "The representation has not changed since the one whose ETag the request named in If-None-Match; no body.",
      "headers": {
        "ETag": {"$ref": "#/components/headers/ETag"},
        "Cache-Control": {"$ref": "#/components/headers/Cache-Control"}
      }
    }
  },
  "headers": {
    "Retry-After": {
      "description": "Seconds after which the request may succeed (--retry-after, default 5).",
      "required": true,
      "schema": {"type": "integer", "minimum": 0},
      "example": 5
    },
    "WWW-Authenticate": {
      "description": "The authentication scheme the write routes take.",
      "required": true,
      "schema": {"type": "string", "enum": ["Bearer"]}
    },
    "ETag": {
      "description": "A strong entity tag of the answer, a hash of its body: a client holding the answer may revalidate it with If-None-Match.",
      "schema": {"type": "string"},
      "example": "\"3f1c9a0e5b7d2c48a6e1f0b9d8c7a6e5\""
    },
    "Cache-Control": {
      "description": "How a cache may keep the answer: public, max-age=86400 for the answers that are a function of the request (radiance, irradiance, rgb, skydome, the sun at a given time), no-cache for those that change with the server's state (this document, the models); every other answer, errors included, is no-store.",
      "schema": {"type": "string"},
      "example": "public, max-age=86400"
    },
    "Link": {
      "description": "RFC 8288 link to the next page of the list (rel=\"next\"), carrying the cursor; absent on the last page.",
      "schema": {"type": "string"},
      "example": "</v1/evaluations?limit=100&cursor=MjQ>; rel=\"next\""
    }
  },
  "parameters": {
    "limit": {
      "name": "limit",
      "in": "query",
      "required": false,
      "description": "Items per page.",
      "schema": {"type": "integer", "minimum": 1, "maximum": 1000, "default": 100}
    },
    "cursor": {
      "name": "cursor",
      "in": "query",
      "required": false,
      "description": "Opaque position of the next page, as given in the Link header of the previous page; absent: the first page.",
      "schema": {"type": "string"}
    },
    "If-None-Match": {
      "name": "If-None-Match",
      "in": "header",
      "required": false,
      "description": "The ETag of an answer the client holds: 304 Not Modified without a body when it is still current.",
      "schema": {"type": "string"}
    }
  },
  "securitySchemes": {
    "bearer": {
      "type": "http",
      "scheme": "bearer",
      "description": "The token given to the server with --token or CLEARSKY_TOKEN; compared in constant time. Without a token the server refuses every write (403)."
    }
  }
})json");
}

}  // namespace clearsky::api::openapi
