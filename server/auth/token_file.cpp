// Reading the write token from a file (token_file.h).
#include "server/auth/token_file.h"

#include <fstream>
#include <stdexcept>

namespace clearsky::server {

namespace {

constexpr std::size_t kMaxTokenFileBytes = 4096;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::string read_token_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("--token-file " + path.string() + ": cannot be read");
  std::string token;
  char c = 0;
  while (file.get(c)) {
    if (token.size() == kMaxTokenFileBytes)
      throw std::runtime_error("--token-file " + path.string() + ": above " +
                               std::to_string(kMaxTokenFileBytes) + " bytes");
    token.push_back(c);
  }
  if (file.bad()) throw std::runtime_error("--token-file " + path.string() + ": cannot be read");
  while (!token.empty() && is_space(token.back())) token.pop_back();
  if (token.empty()) throw std::runtime_error("--token-file " + path.string() + ": empty");
  for (const char t : token) {
    const auto byte = static_cast<unsigned char>(t);
    if (byte <= 0x20 || byte == 0x7f)
      throw std::runtime_error("--token-file " + path.string() +
                               ": the token holds white space or a control character");
  }
  return token;
}

}  // namespace clearsky::server
