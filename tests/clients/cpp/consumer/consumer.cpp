// The package test's consumer: includes the installed headers and links the installed library.
// Run without a server, it reports the connection error the library raises.
#include <clearsky/client/client.h>

#include <iostream>

int main() {
  clearsky::client::ClientOptions options;
  options.base_url = "http://127.0.0.1:9";
  options.connect_timeout_s = 2;
  try {
    clearsky::client::Client(options).models();
  } catch (const clearsky::client::Error& e) {
    std::cout << e.code() << '\n';
    return e.code() == "connection" ? 0 : 1;
  }
  return 1;
}
