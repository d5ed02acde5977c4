// The per-thread memo of quality statements (quality_statement.h).
#include "api/request/quality_statement.h"

#include <algorithm>
#include <memory>

namespace clearsky::api {

namespace {

// Everything a statement is computed from (quality_setting() is a fixed table per model).
struct Entry {
  std::string model_id;
  QualityLevel level;
  QualityLevel served;
  std::map<std::string, double> setting;
  std::vector<std::string> overridden;
  QualityStatement statement;

  bool states(const RequestQuality& q, QualityLevel s) const {
    return level == q.level && served == s && model_id == q.model_id && setting == q.setting &&
           overridden == q.overridden;
  }
};

// A few models at a few levels; requests that override options may bring new settings each
// time, so the oldest entry makes room.
constexpr std::size_t kEntries = 16;

QualityStatement compute(const RequestQuality& quality, QualityLevel served) {
  QualityStatement out;
  out.summary = quality_summary(quality, served);
  nlohmann::json members = nlohmann::json::object();
  add_quality_members(members, quality, served);
  for (const auto& [key, value] : members.items()) out.members.emplace_back(key, value.dump());
  return out;
}

}  // namespace

const QualityStatement& quality_statement(const RequestQuality& quality, QualityLevel served) {
  thread_local std::vector<std::unique_ptr<Entry>> memo;
  const auto found = std::find_if(memo.begin(), memo.end(),
                                  [&](const auto& e) { return e->states(quality, served); });
  if (found != memo.end()) return (*found)->statement;
  if (memo.size() == kEntries) memo.erase(memo.begin());
  memo.push_back(
      std::make_unique<Entry>(Entry{quality.model_id, quality.level, served, quality.setting,
                                    quality.overridden, compute(quality, served)}));
  return memo.back()->statement;
}

}  // namespace clearsky::api
