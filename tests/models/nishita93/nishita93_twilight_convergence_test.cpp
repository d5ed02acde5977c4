// Nishita93 converges in its sphere and cylinder counts with the sun below the horizon
// (docs/performance.md "Findings", models/nishita93/README.md "The sun at the horizon"). The
// optical length towards a sun below a scattering point's horizon was read, with 128 and more
// cylinders, from the against-axis table, linearly between cylinders R_top / (n_c - 1) apart
// (25 km at 256): too coarse for lengths that change like exp(-(c - R) / H_R) with the ray's
// tangent radius c. Twilight skies then differed between 512 and 1024 spheres and cylinders by
// 16 % (median over the atlas's views, sun 93.1 degrees) and by as much between 256 and 512.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/numeric.h"
#include "models/nishita93/nishita93_tables.h"
#include "tests/support/sanitizers.h"

namespace clearsky {
namespace {

constexpr double kR = 6360e3;

// Rayleigh optical lengths towards the sun from points 37 to 59 km up, the sun 96 to 100
// degrees from the zenith there, where the ray to the sun passes above the ground: the
// scattering points that light a twilight sky (the atlas's sun 93.1 degrees from the
// observer's zenith is that far below the horizon of points a few hundred km away along the
// views). Spheres = cylinders = n. Closer to the horizon the mirrored sun's along-axis lookup
// falls in the last cell inside the sphere, which converges more slowly (docs/performance.md).
std::vector<double> twilight_lengths(int n) {
  const Nishita93Tables tables = Nishita93Tables::build({}, n, n);
  std::vector<double> out;
  for (double altitude_km = 37.3; altitude_km < 59.5; altitude_km += 1.0) {
    for (double sun_deg = 96.05; sun_deg < 100.0; sun_deg += 0.2) {
      const double r = kR + 1e3 * altitude_km;
      const double mu_s = std::cos(degrees_to_radians(sun_deg));
      if (r * std::sin(degrees_to_radians(sun_deg)) <= kR + 1e3) continue;  // (near) shadow
      const auto lengths = tables.sun_optical_lengths(r, mu_s);
      EXPECT_TRUE(lengths.has_value()) << altitude_km << ' ' << sun_deg;
      out.push_back(lengths ? lengths->rayleigh_m : 0.0);
    }
  }
  return out;
}

// The largest relative difference.
double largest_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = std::max(largest, std::abs(a[i] - b[i]) / b[i]);
  return largest;
}

TEST(Nishita93TwilightConvergence, SunLengthsConvergeAsSpheresAndCylindersDouble) {
  CLEARSKY_SKIP_REFINEMENT_UNDER_SANITIZERS();
  const std::vector<double> at_128 = twilight_lengths(128);
  const std::vector<double> at_256 = twilight_lengths(256);
  const std::vector<double> at_512 = twilight_lengths(512);
  ASSERT_GT(at_128.size(), 100u);
  const double d_128 = largest_relative_difference(at_128, at_256);
  const double d_256 = largest_relative_difference(at_256, at_512);
  EXPECT_LT(d_256, 0.4 * d_128) << d_128 << ' ' << d_256;
  EXPECT_LT(d_256, 0.01) << d_128 << ' ' << d_256;
}

}  // namespace
}  // namespace clearsky
