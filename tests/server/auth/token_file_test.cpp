// The write token read from a file (server/auth/token_file.h): the content without its final
// newline; a missing, empty, oversized or mangled file is refused naming the file.
#include "server/auth/token_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

class TokenFile : public ::testing::Test {
 protected:
  std::filesystem::path file_with(const std::string& content) {
    const auto path = temp.path / "token";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << content;
    return path;
  }
  clearsky::testing::TempDir temp;
};

TEST_F(TokenFile, IsTheContentWithoutTheFinalNewline) {
  EXPECT_EQ(read_token_file(file_with("s3cret-T0ken\n")), "s3cret-T0ken");
  EXPECT_EQ(read_token_file(file_with("s3cret\r\n\n")), "s3cret");
  EXPECT_EQ(read_token_file(file_with("s3cret")), "s3cret");
}

TEST_F(TokenFile, RefusesWhatCannotBeAToken) {
  EXPECT_THROW(read_token_file(temp.path / "missing"), std::runtime_error);
  EXPECT_THROW(read_token_file(file_with("")), std::runtime_error);
  EXPECT_THROW(read_token_file(file_with("\n")), std::runtime_error);
  EXPECT_THROW(read_token_file(file_with("two words\n")), std::runtime_error);
  EXPECT_THROW(read_token_file(file_with("a\nb\n")), std::runtime_error);
  EXPECT_THROW(read_token_file(file_with(std::string(5000, 'x'))), std::runtime_error);
  try {
    read_token_file(temp.path / "missing");
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
  }
}

}  // namespace
}  // namespace clearsky::server
