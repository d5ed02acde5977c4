// The bearer token of the write endpoints read from a file (`serve --token-file PATH`), so that
// it never appears on a command line (ps, /proc/PID/cmdline) or in the environment: under
// systemd the file is a credential (LoadCredential=, `--token-file %d/token`,
// deploy/systemd/clearsky.service), under Kubernetes a Secret mounted as a file
// (deploy/kubernetes/). The token is the file's content without its trailing white space (an
// editor's final newline); a file that is missing, unreadable, empty, above 4 KiB, or whose
// token holds white space or control characters is refused (std::runtime_error naming the file),
// so that a server never starts with writes silently disabled or a mangled token.
#pragma once

#include <filesystem>
#include <string>

namespace clearsky::server {

std::string read_token_file(const std::filesystem::path& path);

}  // namespace clearsky::server
