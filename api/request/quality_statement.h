// What an answer states of its quality (quality.h: the Clearsky-Quality-Detail header and the
// quality members of the body), remembered per distinct statement: it depends on the model, the
// level asked and served, the options used and the ones overridden, which repeat from request to
// request, and writing it (an ostringstream and a small JSON DOM) cost as much as a Preetham
// radiance answer's own numbers (callgrind of BM_RadianceHandler_Preetham).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "api/request/quality.h"

namespace clearsky::api {

struct QualityStatement {
  std::string summary;  // quality_summary()
  // add_quality_members()' members as dump() writes them: (key, value's JSON text), key order.
  std::vector<std::pair<std::string, std::string>> members;
};

// The statement of (quality, served), from a small per-thread memo (no lock on the request
// path). The reference is valid until the thread's next call.
const QualityStatement& quality_statement(const RequestQuality& quality, QualityLevel served);

}  // namespace clearsky::api
