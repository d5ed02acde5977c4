// Client text in answers: an error message may quote what the client sent (a value, a
// parameter's name, a path), and every answer is JSON, which is UTF-8 (RFC 8259 section 8.1).
// Bytes that are not UTF-8 are replaced, never passed on (nlohmann's serializer would throw on
// them, docs/request-parsing.md "The request edge").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace clearsky::api {

// Whether text is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates).
bool is_valid_utf8(std::string_view text);
// text with every byte that is not part of a well-formed UTF-8 sequence replaced by U+FFFD
// (the replacement character); well-formed text is returned as it is.
std::string replace_invalid_utf8(std::string_view text);
// The same for text quoted in an answer: at most max_bytes of it (a sequence cut at the end is
// replaced too), then "..." when it was longer.
std::string quoted_client_text(std::string_view text, std::size_t max_bytes);

}  // namespace clearsky::api
