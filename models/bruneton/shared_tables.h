// Bruneton tables in memory, one copy per description (BrunetonModel::table_description):
// Bruneton and Elek of one configuration, and any two configurations whose tables are equal,
// share the tables while either model lives (docs/tables-and-memory.md "Shared tables").
// A build of a description already under way in another thread is waited for, not repeated.
// context.reuse_live_tables false: always make() (nothing shared, nothing registered).
// Thread-safe.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "models/bruneton/bruneton_tables.h"
#include "models/core/precompute_context.h"

namespace clearsky::bruneton {

struct SharedTablesResult {
  std::shared_ptr<const Tables> tables;
  bool made = false;  // make() ran here (false: tables another model already holds)
};

// The live tables of this description, else those of a build of it in progress elsewhere
// (waited for; PrecomputeCancelled if context is cancelled meanwhile), else make()'s. When the
// build waited for fails, the waiter builds in its turn. Tables are kept only while a model
// holds them (nothing is cached here beyond their lifetime).
SharedTablesResult shared_tables(const std::string& description,
                                 const std::function<Tables()>& make,
                                 const PrecomputeContext& context);

}  // namespace clearsky::bruneton
