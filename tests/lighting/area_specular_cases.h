// Random shading points for the area lights' specular (fixed seeds): a light, a point and normal as
// area_light_cases.h makes them, a view and a roughness; and the GGX lobe's radiance there by the
// double-precision reference, by linearly transformed cosines and by representative points
// (area_lights.glsl's two paths, in C++). Fresnel is 1 and there is no multiple-scattering scale:
// both methods multiply by the same factors for them. For the tests and lumagraph-bench-area-specular.
#pragma once

#include <vector>

#include "tests/lighting/area_light_cases.h"

namespace lg {

enum class LightShape { kSphere, kTube, kRect };
const char* shape_name(LightShape shape);

struct SpecularCase {
  LightShape shape;
  SphereLightD sphere;  // the one `shape` names, rounded to float as the shaders see it
  TubeLightD tube;
  RectLightD rect;
  glm::dvec3 p, n, v;  // rounded likewise
  double roughness;
  double distance;  // from the light's centre, in bounding radii
  Horizon horizon;
};

struct SpecularRange {
  Horizon horizon;
  double min_distance = 1.5, max_distance = 50.0;  // bounding radii
  double min_roughness = 0.1, max_roughness = 1.0;
  double min_n_dot_v = 0.02;  // views from head-on to this grazing, n.v uniform
};

SpecularCase make_specular_case(CaseGenerator& g, LightShape shape, const SpecularRange& range);

struct SpecularSample {
  double reference;             // L integral of f (n.l) over the light, Fresnel 1
  double ltc;                   // L I (A + B)
  double representative_point;  // f (n.l) L area / d^2 normalization at the point
  double albedo;                // L (A + B): all the lobe could gather
};

SpecularSample evaluate_specular(const SpecularCase& c, double rel_tol = 1e-5);

// Errors over a set of samples, for one method, each sample's values taken as fractions of its
// lobe's albedo L (A + B) (so that bright lights and near ones do not outweigh the rest).
struct SpecularErrors {
  // RMS of (method - reference) over the mean reference: as an image's relative RMS, where the
  // points that catch the lobe's peak weigh most. The 2% bound is on this.
  double relative_rms = 0.0;
  // RMS and max of (method - reference) / reference over the lit samples: every point alike,
  // the lobe's tails as much as its peak.
  double pointwise_rms = 0.0;
  double max_pointwise = 0.0;
  int lit = 0;  // samples whose reference is at least kLitShare of the albedo
};
// A light that gathers less than this share of the lobe's energy adds under 1% of its specular;
// relative errors there compare almost nothing.
inline constexpr double kLitShare = 1e-2;
SpecularErrors ltc_errors(const std::vector<SpecularSample>& samples);
SpecularErrors representative_point_errors(const std::vector<SpecularSample>& samples);

}  // namespace lg
