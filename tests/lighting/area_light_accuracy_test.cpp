// The real-time diffuse formulas against the reference quadrature, on fresh random
// configurations from fixed seeds. Above the horizon, the acceptance criterion: max
// relative error <= 1% for sphere, tube and rectangle lights 1.5 to 50 times their bounding
// radius away. Across the horizon and near the light the errors are printed (and recorded as
// test properties) and held to looser bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <iostream>
#include <string>

#include "nodes/lighting/deferred/area_light_formulas.h"
#include "nodes/lighting/deferred/area_light_reference.h"
#include "tests/lighting/area_light_cases.h"

namespace lg {
namespace {

using glm::dvec3;

// The reference is asked for 1e-8: a thousand times below the float formulas' errors.
constexpr double kReferenceTol = 1e-8;
constexpr int kCases = 2000;

struct Sample {
  double reference;
  double formula;
  double scale;  // the bounding sphere's head-on irradiance
};

struct Range {
  Horizon horizon;
  double min_distance;
  double max_distance;
};

using Sampler = std::function<Sample(CaseGenerator&, const Range&)>;

// Each configuration is rounded to float first and the reference integrates the rounded one,
// so the errors measure the formulas, not the rounding of their input (which alone moves a
// light seen edge-on by more than 1%).
Shading rounded(Shading s) {
  s.p = dvec3(to_float(s.p));
  s.n = dvec3(to_float(s.n));
  return s;
}

Sample sphere_sample(CaseGenerator& g, const Range& r) {
  SphereLightD light = rounded(g.sphere());
  Shading s = rounded(
      g.shading(light.center, light.radius, light.radiance, r.horizon, dvec3(0.0), r.min_distance, r.max_distance));
  return Sample{reference_sphere_irradiance(light, s.p, s.n, kReferenceTol).value,
                sphere_irradiance(to_float(light), to_float(s.p), to_float(s.n)), s.bound_irradiance};
}

Sample tube_sample(CaseGenerator& g, const Range& r) {
  TubeLightD light = rounded(g.tube());
  Shading s = rounded(g.shading(light_center(light), bounding_radius(light), light.radiance, r.horizon, dvec3(0.0),
                                r.min_distance, r.max_distance));
  return Sample{reference_tube_irradiance(light, s.p, s.n, kReferenceTol).value,
                tube_irradiance(to_float(light), to_float(s.p), to_float(s.n)), s.bound_irradiance};
}

Sample rect_sample(CaseGenerator& g, const Range& r) {
  RectLightD light = rounded(g.rect());
  dvec3 front = light.two_sided ? dvec3(0.0) : glm::cross(light.half_x, light.half_y);
  Shading s = rounded(g.shading(light.center, bounding_radius(light), light.radiance, r.horizon, front, r.min_distance,
                                r.max_distance));
  return Sample{reference_rect_irradiance(light, s.p, s.n, kReferenceTol).value,
                rect_irradiance(to_float(light), to_float(s.p), to_float(s.n)), s.bound_irradiance};
}

// Relative errors over the cases the light lights at all (reference above 1e-3 of the scale:
// below it a relative error measures float rounding of nothing), and errors relative to the
// scale over every case.
struct Stats {
  double max_relative = 0.0;
  double max_relative_all = 0.0;  // over every case, lit or not
  double sum_relative = 0.0;
  int lit = 0;
  double max_scaled = 0.0;
  int cases = 0;

  void add(const Sample& s) {
    ++cases;
    double diff = std::fabs(s.formula - s.reference);
    max_scaled = std::max(max_scaled, diff / s.scale);
    if (s.reference > 0.0) max_relative_all = std::max(max_relative_all, diff / s.reference);
    if (s.reference > 1e-3 * s.scale) {
      ++lit;
      max_relative = std::max(max_relative, diff / s.reference);
      sum_relative += diff / s.reference;
    }
  }
};

Stats measure(const Sampler& sampler, uint64_t seed, const Range& range, const std::string& name) {
  CaseGenerator g(seed);
  Stats stats;
  for (int i = 0; i < kCases; ++i) {
    Sample s = sampler(g, range);
    EXPECT_TRUE(std::isfinite(s.formula)) << name << " case " << i;
    stats.add(s);
  }
  double mean = stats.lit ? stats.sum_relative / stats.lit : 0.0;
  std::cout << name << ": " << stats.cases << " cases, " << stats.lit << " lit; relative error max "
            << stats.max_relative << ", mean " << mean << "; max error / bounding-sphere irradiance "
            << stats.max_scaled << "; relative error max over all " << stats.max_relative_all << "\n";
  testing::Test::RecordProperty(name + "_max_relative_error", std::to_string(stats.max_relative));
  testing::Test::RecordProperty(name + "_mean_relative_error", std::to_string(mean));
  testing::Test::RecordProperty(name + "_max_scaled_error", std::to_string(stats.max_scaled));
  testing::Test::RecordProperty(name + "_max_relative_error_all", std::to_string(stats.max_relative_all));
  return stats;
}

// The acceptance criterion of issue 3, over every case, however dim (a rectangle seen edge-on).
constexpr double kAboveHorizon = 0.01;
const Range kFar{Horizon::kAbove, 1.5, 50.0};

TEST(AreaLightAccuracy, SphereAboveHorizonWithinOnePercent) {
  Stats s = measure(sphere_sample, 201, kFar, "sphere_above");
  EXPECT_LE(s.max_relative_all, kAboveHorizon);
}

TEST(AreaLightAccuracy, TubeAboveHorizonWithinOnePercent) {
  Stats s = measure(tube_sample, 202, kFar, "tube_above");
  EXPECT_LE(s.max_relative_all, kAboveHorizon);
}

TEST(AreaLightAccuracy, RectAboveHorizonWithinOnePercent) {
  Stats s = measure(rect_sample, 203, kFar, "rect_above");
  EXPECT_LE(s.max_relative_all, kAboveHorizon);
}

// Across the horizon. The formulas clip exactly, so a loose 1% relative bound (on lit cases)
// and 1e-4 of the scale (on all) catch a wrong clip, which costs tens of percent, while
// leaving room for float rounding where the horizon meets a silhouette almost tangentially
// (measured: up to 0.14% relative and 3e-6 of the scale). Below 1e-3 of the scale relative
// errors are printed but not bounded: they compare rounding with almost nothing.
constexpr double kCrossingRelative = 0.01;
constexpr double kCrossingScaled = 1e-4;
const Range kCrossing{Horizon::kCrossing, 1.5, 50.0};

TEST(AreaLightAccuracy, SphereAcrossHorizon) {
  Stats s = measure(sphere_sample, 211, kCrossing, "sphere_crossing");
  EXPECT_LE(s.max_relative, kCrossingRelative);
  EXPECT_LE(s.max_scaled, kCrossingScaled);
}

TEST(AreaLightAccuracy, TubeAcrossHorizon) {
  Stats s = measure(tube_sample, 212, kCrossing, "tube_crossing");
  EXPECT_LE(s.max_relative, kCrossingRelative);
  EXPECT_LE(s.max_scaled, kCrossingScaled);
}

TEST(AreaLightAccuracy, RectAcrossHorizon) {
  Stats s = measure(rect_sample, 213, kCrossing, "rect_crossing");
  EXPECT_LE(s.max_relative, kCrossingRelative);
  EXPECT_LE(s.max_scaled, kCrossingScaled);
}

// Close to the light (1.02 to 1.5 bounding radii), either side of the horizon: outside the
// criterion's range, reported and held to the crossing bounds.
const Range kNearAbove{Horizon::kAbove, 1.02, 1.5};
const Range kNearCrossing{Horizon::kCrossing, 1.02, 1.5};

TEST(AreaLightAccuracy, NearField) {
  for (const auto& [sampler, name, seed] :
       {std::tuple{Sampler(sphere_sample), "sphere", 221}, std::tuple{Sampler(tube_sample), "tube", 222},
        std::tuple{Sampler(rect_sample), "rect", 223}}) {
    for (const auto& [range, where] :
         {std::pair{kNearAbove, "_near_above"}, std::pair{kNearCrossing, "_near_crossing"}}) {
      Stats s = measure(sampler, seed, range, std::string(name) + where);
      EXPECT_LE(s.max_relative, kCrossingRelative) << name << where;
      EXPECT_LE(s.max_scaled, kCrossingScaled) << name << where;
    }
  }
}

}  // namespace
}  // namespace lg
