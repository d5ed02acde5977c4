// The HTTP exchange of the client library (http_transport.h).
#include "http_transport.h"

#include <httplib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>
#include <utility>

namespace clearsky::client {

namespace {

// What one attempt brought back: an answer (any status) or no answer at all.
struct Attempt {
  int status = 0;
  httplib::Headers headers;
  std::string body;
  httplib::Error transport_error = httplib::Error::Success;
};

Attempt attempt_of(const httplib::Result& result) {
  Attempt attempt;
  if (!result) {
    attempt.transport_error = result.error();
    return attempt;
  }
  attempt.status = result->status;
  attempt.headers = result->headers;
  attempt.body = result->body;
  return attempt;
}

std::string header(const httplib::Headers& headers, const char* name) {
  // cpp-httplib compares header names without regard to case (RFC 9110 section 5.1).
  const auto it = headers.find(name);
  return it == headers.end() ? std::string() : it->second;
}

// Retry-After as delta-seconds (RFC 9110 section 10.2.3), the form the server sends.
std::optional<int> retry_after_s(const httplib::Headers& headers) {
  const std::string text = header(headers, "Retry-After");
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return std::stoi(text);
}

// The server's error body {"error": {"code", "message", "parameter"}}; a body without it (a
// proxy's page) still gives the status.
Error error_of(const Attempt& attempt) {
  if (attempt.status == 0) {
    const bool cancelled = attempt.transport_error == httplib::Error::Canceled;
    return Error(0, cancelled ? "cancelled" : "connection",
                 cancelled ? "the request was cancelled"
                           : "no answer: " + httplib::to_string(attempt.transport_error));
  }
  const auto retry = retry_after_s(attempt.headers);
  const nlohmann::json body = nlohmann::json::parse(attempt.body, nullptr, false);
  if (body.is_object() && body.contains("error") && body["error"].is_object()) {
    const nlohmann::json& e = body["error"];
    const auto text = [&e](const char* name) {
      const auto it = e.find(name);
      return it != e.end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    return Error(attempt.status, text("code"), text("message"), text("parameter"), retry);
  }
  return Error(attempt.status, "http_" + std::to_string(attempt.status),
               attempt.body.substr(0, 512), "", retry);
}

HttpAnswer answer_of(const Attempt& attempt) {
  HttpAnswer answer;
  answer.status = attempt.status;
  answer.body = attempt.body;
  answer.location = header(attempt.headers, "Location");
  answer.link = header(attempt.headers, "Link");
  answer.content_type = header(attempt.headers, "Content-Type");
  return answer;
}

std::unique_ptr<httplib::Client> connection(const ClientOptions& options) {
  auto client = std::make_unique<httplib::Client>(options.base_url);
  client->set_connection_timeout(options.connect_timeout_s, 0);
  client->set_read_timeout(options.read_timeout_s, 0);
  client->set_write_timeout(options.write_timeout_s, 0);
  if (!options.token.empty()) client->set_bearer_token_auth(options.token.c_str());
  return client;
}

// Runs `once` until it answers something other than a 503/429 with an acceptable Retry-After,
// or the retries are spent; an error answer becomes Error.
template <typename Once>
Attempt with_retries(const ClientOptions& options, Once&& once) {
  for (int attempt_number = 1;; ++attempt_number) {
    Attempt attempt = once();
    const bool retryable = attempt.status == 503 || attempt.status == 429;
    const auto wait_s = retry_after_s(attempt.headers);
    if (retryable && wait_s && attempt_number <= options.max_retries &&
        *wait_s <= options.max_retry_wait_s) {
      if (options.on_retry) {
        RetryNotice notice;
        notice.attempt = attempt_number;
        notice.status = attempt.status;
        notice.code = error_of(attempt).code();
        notice.wait_s = *wait_s;
        options.on_retry(notice);
      }
      std::this_thread::sleep_for(std::chrono::seconds(*wait_s));
      continue;
    }
    if (attempt.status == 0 || attempt.status >= 400) throw error_of(attempt);
    return attempt;
  }
}

}  // namespace

HttpTransport::HttpTransport(ClientOptions options) : options_(std::move(options)) {}

HttpAnswer HttpTransport::get(const std::string& target) const {
  return answer_of(
      with_retries(options_, [&] { return attempt_of(connection(options_)->Get(target)); }));
}

HttpAnswer HttpTransport::post_json(const std::string& target, const std::string& json) const {
  return answer_of(with_retries(options_, [&] {
    return attempt_of(connection(options_)->Post(target, json, "application/json"));
  }));
}

HttpAnswer HttpTransport::post_empty(const std::string& target) const {
  return answer_of(
      with_retries(options_, [&] { return attempt_of(connection(options_)->Post(target)); }));
}

HttpAnswer HttpTransport::remove(const std::string& target) const {
  return answer_of(
      with_retries(options_, [&] { return attempt_of(connection(options_)->Delete(target)); }));
}

HttpAnswer HttpTransport::post_file(const std::string& target, const std::filesystem::path& file,
                                    const UploadProgress& progress) const {
  std::error_code size_error;
  const std::uintmax_t total_bytes = std::filesystem::file_size(file, size_error);
  if (size_error)
    throw Error(0, "unreadable_file", file.string() + ": " + size_error.message(), "archive");
  return answer_of(with_retries(options_, [&] {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(0, "unreadable_file", file.string() + ": cannot be opened", "archive");
    std::array<char, 64 * 1024> buffer{};
    const auto provide = [&](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
      in.seekg(static_cast<std::streamoff>(offset));
      in.read(buffer.data(),
              static_cast<std::streamsize>(std::min<std::size_t>(length, buffer.size())));
      const auto n = static_cast<std::size_t>(in.gcount());
      if (n == 0 || !sink.write(buffer.data(), n)) return false;
      return !progress || progress(offset + n, total_bytes);
    };
    return attempt_of(connection(options_)->Post(target, static_cast<std::size_t>(total_bytes),
                                                 provide, "application/octet-stream"));
  }));
}

SkydomeDownload HttpTransport::get_to_stream(const std::string& target, std::ostream& out) const {
  SkydomeDownload download;
  with_retries(options_, [&] {
    int status = 0;
    std::string error_body;
    const auto on_head = [&](const httplib::Response& response) {
      status = response.status;
      if (status < 300) download.content_type = response.get_header_value("Content-Type");
      return true;
    };
    const auto on_bytes = [&](const char* data, std::size_t n) {
      if (status >= 300) {
        // An error body is one small JSON object; a larger one is cut (its start is enough).
        if (error_body.size() < 64 * 1024) error_body.append(data, n);
        return true;
      }
      out.write(data, static_cast<std::streamsize>(n));
      download.bytes += n;
      return static_cast<bool>(out);
    };
    Attempt attempt = attempt_of(connection(options_)->Get(target, on_head, on_bytes));
    if (attempt.status == 0 && status >= 200 && status < 300) {
      if (!out)
        throw Error(0, "write_failed",
                    "the output stream failed after " + std::to_string(download.bytes) + " bytes");
      throw Error(0, "connection",
                  "the answer broke off after " + std::to_string(download.bytes) +
                      " bytes: " + httplib::to_string(attempt.transport_error));
    }
    attempt.body = std::move(error_body);
    return attempt;
  });
  return download;
}

std::optional<std::string> next_cursor(const std::string& link) {
  if (link.find("rel=\"next\"") == std::string::npos) return std::nullopt;
  const auto open = link.find('<');
  const auto close = link.find('>', open);
  if (open == std::string::npos || close == std::string::npos) return std::nullopt;
  const std::string target = link.substr(open + 1, close - open - 1);
  const auto query = target.find('?');
  if (query == std::string::npos) return std::nullopt;
  httplib::Params params;
  httplib::detail::parse_query_text(target.substr(query + 1), params);
  const auto cursor = params.find("cursor");
  if (cursor == params.end()) return std::nullopt;
  return cursor->second;
}

}  // namespace clearsky::client
