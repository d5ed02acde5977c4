// The quality tables (models/quality/<id>.csv, docs/quality-levels.md): every registered model
// has its three levels, each level's options are options its descriptor lists within their
// ranges, standard is the model's defaults, and the parser refuses malformed tables.
#include "models/quality/quality_levels.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/sky_model.h"
#include "models/registry.h"

namespace clearsky {
namespace {

const ParameterSpec* find_option(const ModelDescriptor& d, const std::string& name) {
  for (const ParameterSpec& p : d.parameters) {
    if (p.name == name && !p.atmosphere) return &p;
  }
  return nullptr;
}

TEST(QualityLevels, EveryRegisteredModelHasItsThreeLevels) {
  for (const ModelFactory& f : registered_models()) {
    const std::string& id = f.descriptor->id;
    const auto text = embedded_quality_table(id);
    ASSERT_TRUE(text.has_value()) << "models/quality/" << id << ".csv is missing";
    const auto table = parse_quality_table(*text);
    // A table may say, in a comment line starting "# errors not measured", that the errors of
    // its draft and standard rows were not measured: they are then left out (the answers say
    // null), never copied from another model.
    const bool unmeasured = text->find("\n# errors not measured") != std::string_view::npos ||
                            text->rfind("# errors not measured", 0) == 0;
    for (QualityLevel level : kQualityLevels) {
      const QualitySetting& row = table[static_cast<std::size_t>(level)];
      EXPECT_EQ(row.level, level) << id;
      if (unmeasured && level != QualityLevel::reference) {
        EXPECT_FALSE(row.p95_relative_error || row.max_relative_error)
            << id << " " << to_string(level) << ": figures in a table that says it has none";
        continue;
      }
      // Every level states its error against the reference; the reference's is 0 against
      // itself or its difference to a finer check, below every other level's.
      ASSERT_TRUE(row.p95_relative_error && row.max_relative_error)
          << id << " " << to_string(level);
      EXPECT_GE(*row.max_relative_error, *row.p95_relative_error) << id;
      if (level == QualityLevel::reference) {
        for (QualityLevel other : {QualityLevel::draft, QualityLevel::standard}) {
          const QualitySetting& o = table[static_cast<std::size_t>(other)];
          if (o.p95_relative_error) {
            EXPECT_LE(*row.p95_relative_error, *o.p95_relative_error) << id;
          }
        }
      }
    }
  }
}

TEST(QualityLevels, EachLevelsOptionsAreValidForTheModel) {
  for (const ModelFactory& f : registered_models()) {
    const ModelDescriptor& d = *f.descriptor;
    for (QualityLevel level : kQualityLevels) {
      const QualitySetting& row = quality_setting(d.id, level);
      for (const auto& [name, value] : row.options) {
        const ParameterSpec* spec = find_option(d, name);
        ASSERT_NE(spec, nullptr) << d.id << " has no option " << name;
        EXPECT_GE(value, spec->min_value) << d.id << " " << name;
        EXPECT_LE(value, spec->max_value) << d.id << " " << name;
        if (spec->integer) {
          EXPECT_EQ(value, std::floor(value)) << d.id << " " << name;
        }
      }
      ModelConfig config;
      apply_quality_level(d, row, config.options);
      EXPECT_NO_THROW(validate_config(d, config)) << d.id << " " << to_string(level);
    }
  }
}

TEST(QualityLevels, StandardIsTheDefaults) {
  for (const ModelFactory& f : registered_models()) {
    const ModelDescriptor& d = *f.descriptor;
    const QualitySetting& standard = quality_setting(d.id, QualityLevel::standard);
    for (const auto& [name, value] : standard.options) {
      const ParameterSpec* spec = find_option(d, name);
      ASSERT_NE(spec, nullptr) << d.id << " " << name;
      EXPECT_EQ(value, spec->default_value) << d.id << " " << name;
    }
    // Applied, it leaves a configuration (hence every cache key) as it was.
    ModelConfig config;
    EXPECT_TRUE(apply_quality_level(d, standard, config.options).empty());
    EXPECT_EQ(config.canonical_string(), ModelConfig{}.canonical_string()) << d.id;
  }
}

TEST(QualityLevels, ModelsWithoutCostOptionsHaveOneSettingAtEveryLevel) {
  for (const char* id : {"preetham"}) {
    for (QualityLevel level : kQualityLevels) {
      const QualitySetting& row = quality_setting(id, level);
      EXPECT_TRUE(row.options.empty()) << id;
      EXPECT_EQ(row.p95_relative_error, 0.0) << id;
      EXPECT_EQ(row.max_relative_error, 0.0) << id;
    }
  }
}

// The atlas's rule for the models it has measured with a converged reference (docs/performance.md
// "Quality levels"): the draft is within 2% of the reference at the 95th percentile, whatever it
// costs against the study's setting, and the reference is checked (its own error is its
// difference to a finer setting, not zero by fiat).
TEST(QualityLevels, DraftsOfConvergedModelsAreWithinTwoPercent) {
  for (const char* id : {"oneal", "hosek"}) {
    const QualitySetting& draft = quality_setting(id, QualityLevel::draft);
    EXPECT_LE(draft.p95_relative_error, 0.02) << id;
    EXPECT_GT(draft.p95_relative_error, 0.0) << id;  // a setting of its own, measured
  }
  EXPECT_EQ(quality_setting("oneal", QualityLevel::draft).options.at("samples"), 64.0);
  EXPECT_EQ(quality_setting("oneal", QualityLevel::reference).options.at("samples"), 512.0);
  EXPECT_LT(quality_setting("oneal", QualityLevel::reference).p95_relative_error,
            quality_setting("oneal", QualityLevel::draft).p95_relative_error);
  EXPECT_EQ(quality_setting("hosek", QualityLevel::draft).options.at("native_bands"), 1.0);
  EXPECT_EQ(quality_setting("hosek", QualityLevel::standard).p95_relative_error, 0.0);
}

TEST(QualityLevels, TheLevelsOfATableModelDiffer) {
  const auto& draft = quality_setting("bruneton", QualityLevel::draft).options;
  const auto& standard = quality_setting("bruneton", QualityLevel::standard).options;
  const auto& reference = quality_setting("bruneton", QualityLevel::reference).options;
  EXPECT_LT(draft.at("table_mu_size"), standard.at("table_mu_size"));
  EXPECT_GT(reference.at("table_mu_size"), standard.at("table_mu_size"));
}

TEST(QualityLevels, ExplicitOptionsWinOverTheLevel) {
  const ModelDescriptor& d = *find_model("oneal")->descriptor;
  const QualitySetting& draft = quality_setting("oneal", QualityLevel::draft);
  std::map<std::string, double> options{{"samples", 8.0}};
  EXPECT_EQ(apply_quality_level(d, draft, options), std::vector<std::string>{"samples"});
  EXPECT_EQ(options.at("samples"), 8.0);
  EXPECT_EQ(resolved_quality_options(draft, options).at("samples"), 8.0);
  // The level's own value given explicitly is no override.
  std::map<std::string, double> same{{"samples", draft.options.at("samples")}};
  EXPECT_TRUE(apply_quality_level(d, draft, same).empty());
  std::map<std::string, double> none;
  apply_quality_level(d, draft, none);
  EXPECT_EQ(none.at("samples"), draft.options.at("samples"));
}

TEST(QualityLevels, LevelNames) {
  for (QualityLevel level : kQualityLevels) EXPECT_EQ(parse_quality_level(to_string(level)), level);
  EXPECT_FALSE(parse_quality_level("best").has_value());
  EXPECT_FALSE(parse_quality_level("Draft").has_value());
}

TEST(QualityLevels, TheParserRefusesMalformedTables) {
  const std::string header =
      "level,options,p95_relative_error,max_relative_error,build_seconds,table_bytes\n";
  const std::string ok =
      header + "draft,n=1,0.1,0.2,,\nstandard,n=2,0.01,0.02,,\nreference,n=3,0,0,,\n";
  const auto table = parse_quality_table("# a comment\n" + ok);
  EXPECT_EQ(table[0].options.at("n"), 1.0);
  EXPECT_FALSE(table[0].build_seconds.has_value());
  const std::string bad[] = {
      "",                                                          // no header
      "level,options\n",                                           // another header
      header + "draft,n=1,0.1,0.2,,\nstandard,n=2,0.01,0.02,,\n",  // reference missing
      header + "draft,n=1,0.1,0.2,,\ndraft,n=1,0.1,0.2,,\nreference,,0,0,,\nstandard,,0,0,,\n",
      header + "best,n=1,0.1,0.2,,\n",                                      // unknown level
      header + "draft,n=x,0.1,0.2,,\nstandard,,0,0,,\nreference,,0,0,,\n",  // not a number
      header + "draft,n,0.1,0.2,,\nstandard,,0,0,,\nreference,,0,0,,\n",    // no value
      header + "draft,n=1,0.1,0.2\nstandard,,0,0,,\nreference,,0,0,,\n",    // columns missing
  };
  for (const std::string& text : bad)
    EXPECT_THROW(parse_quality_table(text), std::invalid_argument) << text;
}

TEST(QualityLevels, AModelWithoutATableHasOnlyItsDefaults) {
  for (QualityLevel level : kQualityLevels) {
    const QualitySetting& row = quality_setting("no-such-model", level);
    EXPECT_EQ(row.level, level);
    EXPECT_TRUE(row.options.empty());
    EXPECT_FALSE(row.p95_relative_error.has_value());
  }
}

}  // namespace
}  // namespace clearsky
