// The one parser of JSON a client sends (request bodies, and the CLI's JSON options). Besides
// the syntax (RFC 8259) it bounds what the rest of the code can meet
// (docs/request-parsing.md "The request edge"):
// - nesting: at most kMaxJsonDepth levels of arrays and objects. nlohmann's parser is
//   iterative, but copying, dumping and destroying a tree, and our own walks of it, recurse:
//   a body nested 100,000 deep (600 KB) overflowed the stack. The parse stops at the first
//   level beyond the limit, before the tree is deeper than it;
// - numbers: each finite as a double (nlohmann refuses 1e999, -1e999 and a 400-digit integer
//   with out_of_range 406, which is a 400 here, not a 500);
// - strings: UTF-8 (nlohmann refuses anything else).
// Every refusal is a 400 naming the top-level member being read (`views`, `altitude`), or the
// whole (`body`) outside any member.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace clearsky::api {

// Arrays and objects nested in one another, the outermost counted: {"views": [[1, 2]]} is 3.
inline constexpr int kMaxJsonDepth = 64;

// whole names the text in errors outside any member ("body", or a CLI option).
nlohmann::json parse_client_json(std::string_view text, const std::string& whole = "body");

}  // namespace clearsky::api
