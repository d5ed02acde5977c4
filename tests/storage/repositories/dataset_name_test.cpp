// Tests of the dataset name rule (storage/repositories/dataset_name.h), with the names that
// were imported but could then be neither read nor deleted over HTTP.
#include "storage/repositories/dataset_name.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace clearsky::storage {
namespace {

TEST(DatasetName, TheRuleKeepsNamesThatAreOnePathSegment) {
  for (const std::string& name :
       std::vector<std::string>{"kider2014", "a", "Z9", "day-1.v2_b", std::string(128, 'n')})
    EXPECT_TRUE(is_valid_dataset_name(name)) << name;
  for (const std::string& name : std::vector<std::string>{
           "a/b", "../x", "..", ".", "", std::string(5000, 'a'), std::string(129, 'n'), "-x", ".x",
           "_x", "a b", "a%2Fb", "a\\b", "caf\xc3\xa9", std::string("a\0b", 3)})
    EXPECT_FALSE(is_valid_dataset_name(name)) << name;
}

}  // namespace
}  // namespace clearsky::storage
