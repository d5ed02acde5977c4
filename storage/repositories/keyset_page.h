// One page of a list read by keyset pagination (docs/data-api.md "Pagination"): the rows come
// in a fixed order of a unique key (an id or a name) and a page starts after the last key of
// the previous one, so that rows inserted or deleted meanwhile never shift a page. The
// repositories read limit + 1 rows to know whether another page follows.
#pragma once

#include <cstdint>
#include <vector>

namespace clearsky::storage {

template <typename Row>
struct KeysetPage {
  std::vector<Row> rows;
  bool more = false;  // another page follows the last row
};

// Trims rows read with LIMIT limit + 1 to limit, noting whether there were more.
template <typename Row>
KeysetPage<Row> keyset_page(std::vector<Row> rows, std::int64_t limit) {
  KeysetPage<Row> page;
  page.more = static_cast<std::int64_t>(rows.size()) > limit;
  if (page.more) rows.resize(static_cast<std::size_t>(limit));
  page.rows = std::move(rows);
  return page;
}

}  // namespace clearsky::storage
