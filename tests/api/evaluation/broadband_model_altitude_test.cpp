// The altitude of a model's broadband answer for a site
// (api/evaluation/broadband_model_altitude.h): Bruneton and Nishita 1993 answer at the site's
// elevation; Haber answers at the ground only, and the note says so by name rather than
// clamping in silence; a site below sea level is below every model's ground.
#include "api/evaluation/broadband_model_altitude.h"

#include <gtest/gtest.h>

#include "models/registry.h"

namespace clearsky::api {
namespace {

const ModelDescriptor& descriptor_of(const std::string& id) {
  const ModelFactory* factory = find_model(id);
  EXPECT_NE(factory, nullptr) << id;
  return *factory->descriptor;
}

TEST(BroadbandModelAltitude, ModelsThatAnswerAltitudesAnswerAtTheSiteElevation) {
  for (const char* id : {"bruneton", "nishita93", "nishita96", "oneal"}) {
    const ModelAltitude a = model_altitude_for_site(descriptor_of(id), 250.0);
    EXPECT_TRUE(a.at_site_elevation) << id;
    EXPECT_EQ(a.altitude_m, 250.0) << id;
    EXPECT_EQ(model_altitude_note(descriptor_of(id), {250.0, 250.0}),
              "model at the site's elevation (altitude 250 m)");
  }
}

TEST(BroadbandModelAltitude, HaberAnswersAtTheGroundAndTheNoteSaysSo) {
  const ModelAltitude a = model_altitude_for_site(descriptor_of("haber"), 250.0);
  EXPECT_FALSE(a.at_site_elevation);
  EXPECT_EQ(a.altitude_m, 0.0);
  const std::string note = model_altitude_note(descriptor_of("haber"), {250.0});
  EXPECT_NE(note.find("not at the site's elevation (250 m)"), std::string::npos) << note;
  EXPECT_NE(note.find("haber answers altitudes 0..0 m only"), std::string::npos) << note;
  EXPECT_FALSE(model_altitude_for_site(descriptor_of("bruneton"), -20.0).at_site_elevation);
}

}  // namespace
}  // namespace clearsky::api
