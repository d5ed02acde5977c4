// Data services, connections and the clock for the data routes (data_access.h).
#include "api/routes/data_access.h"

#include <chrono>

namespace clearsky::api {

ApiError no_database(const std::string& parameter) {
  // 404, not 503: the resource is not on this server and never will be (a 503 would invite a
  // retry here); the proxy routes data paths to the writer (docs/deploy.md "Roles").
  return ApiError(404, "no_database", parameter,
                  "this server has no database (serve --role query): datasets, imports, "
                  "evaluations, fits and jobs are served by the writer (serve --role writer)");
}

const DataServices& data_services(const ApiContext& context) {
  if (context.data == nullptr) throw no_database();
  return *context.data;
}

storage::Database open_database(const ApiContext& context) {
  return storage::Database::open(data_services(context).db_path);
}

double now_unix_s() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

}  // namespace clearsky::api
