// The path tracer's light transport, shared by the reference image (path_tracer.h) and the
// probe bakes: paths with next-event estimation at every vertex (each light of PathLights and
// the environment on its own) and BRDF sampling, combined by multiple importance sampling (power
// heuristic), Russian roulette after a few bounces. Every surface met by a ray other than the
// camera's is two-sided (single-sided ones too: see docs/path-tracer.md), shaded on the side the
// ray arrives from with its normal-mapped shading normal, and reflects only into the geometric
// hemisphere it is seen from; alpha-tested surfaces let rays through where RayScene says so.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "nodes/gi/path_tracer/path_scene.h"

namespace lg {

// One path's random numbers: hashes of (seed, path, dimension), so that a path's value does not
// depend on which thread or chunk traced it.
class PathRandom {
 public:
  PathRandom(uint64_t seed, uint64_t path, uint32_t per_bounce) : seed_(seed), path_(path), per_bounce_(per_bounce) {}
  double get(uint32_t bounce, uint32_t dimension) const;
  glm::dvec2 pair(uint32_t bounce, uint32_t dimension) const {
    return {get(bounce, dimension), get(bounce, dimension + 1)};
  }

 private:
  uint64_t seed_, path_;
  uint32_t per_bounce_;
};

// A camera path's value split at the visible surface (path_tracer.h defines each part).
struct PathValue {
  glm::dvec3 emission{0.0}, direct{0.0}, indirect_diffuse{0.0}, specular{0.0};
  glm::dvec3 radiance() const { return emission + direct + indirect_diffuse + specular; }
};

// What a probe sees along one ray: the radiance arriving other than straight from the scene's
// lights (the environment, or the surface met with all it emits and reflects), and how far the
// surface is (infinite on a miss) and whether the ray met its back.
struct ProbeRay {
  glm::dvec3 radiance{0.0};
  double distance = 0.0;
  bool back_face = false;
};

// What the G-buffer holds at a pixel, as the path tracer sees it: the visible surface's position,
// its shading normal on the camera's side, and its diffuse colour toward the camera (base colour
// x (1 - metal) x (1 - the specular albedo at that view): what multiplies irradiance / pi).
struct VisibleSurface {
  glm::dvec3 position, normal, diffuse_color;
};

// A probe's ray cut after its first surface, for updates that take the light of further bounces
// from the probes themselves (probe_update.h): `ray` holds what the surface emits plus what it
// reflects toward the probe of PathLights' lights (the scene's and the sky's sun; light sampling
// alone, as no BRDF sample follows), or on a miss what probe_ray() gives; `surface` is the
// surface met (its normal on the probe's side), where the caller adds the rest of its light as
// albedo / pi x irradiance. `albedo` is one BRDF sample's f cos / pdf toward the probe: its
// expectation is the surface's directional albedo (the diffuse colour plus what the specular lobe
// reflects of light arriving evenly), so rough dielectrics keep their few percent of specular.
struct ProbeHit {
  ProbeRay ray;
  std::optional<VisibleSurface> surface;
  glm::dvec3 albedo{0.0};
};

class PathTransport {
 public:
  // max_bounces: surface interactions per path (1: direct light only); Russian roulette may end
  // a path once it has made `russian_roulette_after` of them.
  PathTransport(const PathScene& scene, uint32_t max_bounces, uint32_t russian_roulette_after = 3);

  // The random dimensions one bounce uses (for PathRandom).
  uint32_t dimensions_per_bounce() const;
  PathValue camera_path(glm::dvec3 eye, glm::dvec3 direction, bool cull_backfaces, const PathRandom& random) const;
  ProbeRay probe_ray(glm::dvec3 origin, glm::dvec3 direction, const PathRandom& random) const;
  ProbeHit probe_hit(glm::dvec3 origin, glm::dvec3 direction, const PathRandom& random) const;
  std::optional<VisibleSurface> visible_surface(glm::dvec3 eye, glm::dvec3 direction, bool cull_backfaces) const;

 private:
  struct State;
  bool step(State& s, uint32_t bounce, const PathRandom& random, PathValue& out) const;
  struct BrdfSample;
  BrdfSample sample_brdf(const State& s, uint32_t bounce, const PathRandom& random) const;
  void sample_lights(State& s, uint32_t bounce, const PathRandom& random, PathValue& out, bool with_mis) const;
  double brdf_pdf(const State& s, glm::dvec3 l) const;
  void reflect(State& s, glm::dvec3 l, glm::dvec3 weight, bool scene_light, PathValue& out) const;
  bool segment(State& s, glm::dvec3 origin, glm::dvec3 l, double pdf, uint32_t bounce, const PathRandom& random,
               PathValue& out, ProbeRay* first_hit) const;
  bool visible(glm::dvec3 position, glm::dvec3 geometric, glm::dvec3 direction, double distance) const;

  const PathScene& scene_;
  uint32_t max_bounces_, russian_roulette_after_;
};

}  // namespace lg
