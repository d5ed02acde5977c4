// The atlas's settings of every registered model (models/atlas/atlas_settings.h): the standard
// setting first and unchanged, every option one the model's descriptor lists and inside its
// range, and every setting and the reference buildable configurations.
#include "models/atlas/atlas_settings.h"

#include <gtest/gtest.h>

#include "models/core/model_factory.h"
#include "models/registry.h"

namespace clearsky::atlas {
namespace {

void expect_valid(const ModelDescriptor& d, const AtlasSetting& s) {
  SCOPED_TRACE(d.id + " " + s.name);
  for (const auto& [name, value] : s.options) {
    const ParameterSpec* p = d.find_parameter(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->atmosphere) << name;
  }
  EXPECT_NO_THROW(validate_config(d, s.config(d)));
}

TEST(AtlasSettings, EveryModelListsTheStandardSettingFirstAndOnlyDeclaredOptions) {
  for (const AtlasScope scope : {AtlasScope::full, AtlasScope::quick}) {
    for (const ModelFactory& f : registered_models()) {
      const ModelDescriptor& d = *f.descriptor;
      const ModelAtlasSettings a = atlas_settings(d, scope);
      ASSERT_GE(a.settings.size(), 2u) << d.id;
      EXPECT_EQ(a.settings[0].name, "standard");
      EXPECT_TRUE(a.settings[0].options.empty());
      EXPECT_EQ(a.settings[0].grid, AtlasGrid::paper_bins);
      EXPECT_EQ(a.reference.grid, AtlasGrid::paper_bins);
      EXPECT_FALSE(a.reference_reason.empty());
      for (const AtlasSetting& s : a.settings) expect_valid(d, s);
      expect_valid(d, a.reference);
      if (!a.reference_check.name.empty()) expect_valid(d, a.reference_check);
      // A numerical model's full atlas checks its reference against one step finer (Elek's
      // reference has Bruneton's tables, checked in Bruneton's atlas).
      if (scope == AtlasScope::full && !a.settings[1].options.empty() && d.id != "hosek" &&
          d.id != "elek") {
        EXPECT_FALSE(a.reference_check.name.empty()) << d.id;
      }
    }
  }
}

TEST(AtlasSettings, TheRgbSettingComputesThePapersThreeWavelengths) {
  const ModelFactory* f = find_model("oneal");
  ASSERT_NE(f, nullptr);
  const ModelAtlasSettings a = atlas_settings(*f->descriptor, AtlasScope::quick);
  const auto rgb = std::find_if(a.settings.begin(), a.settings.end(),
                                [](const AtlasSetting& s) { return s.name == "rgb"; });
  ASSERT_NE(rgb, a.settings.end());
  EXPECT_EQ(rgb->config(*f->descriptor).wavelengths.nanometres(),
            (std::vector<double>{440.0, 550.0, 680.0}));
}

}  // namespace
}  // namespace clearsky::atlas
