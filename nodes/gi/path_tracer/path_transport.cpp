#include "nodes/gi/path_tracer/path_transport.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "nodes/gi/path_tracer/microfacet_brdf.h"
#include "nodes/raytrace/camera_hit.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/ray_offset.h"

namespace lg {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double power_heuristic(double pdf, double other) {
  const double a = pdf * pdf, b = other * other;
  return a + b > 0.0 ? a / (a + b) : 0.0;
}

// A surface point as shading sees it: normals on the side the ray came from.
struct Vertex {
  glm::dvec3 position, geometric;
  BrdfSurface brdf;
  glm::dvec3 emission;
};

Vertex make_vertex(const PathScene& scene, const RayHit& hit, glm::dvec3 position, glm::dvec3 ray_direction) {
  const SurfaceAttributes attributes = scene.surfaces().at(hit.primitive, position);
  const SceneView& view = scene.view();
  const DrawItem& draw = view.draws[attributes.draw];
  const SurfaceMaterial material = sample_material(view, draw, attributes.texcoords);
  glm::dvec3 geometric(hit.normal);
  if (glm::dot(geometric, ray_direction) > 0.0) geometric = -geometric;
  // The normal map bends the front side's normal; a back hit turns the result round, as the
  // G-buffer does. Light that the bent normal faces but the geometric side does not is cut by
  // visible() and the BRDF's own n.l.
  const glm::dvec3 mapped = mapped_normal(view, draw, attributes.texcoords, attributes.normal, attributes.tangent);
  const glm::dvec3 shading = glm::dot(attributes.normal, geometric) < 0.0 ? -mapped : mapped;
  return Vertex{position, geometric, make_brdf_surface(shading, material), material.emissive};
}

// Random dimensions of a bounce: lobe choice, BRDF direction (2), roulette, then 2 per light
// and 2 for the environment.
constexpr uint32_t kLightDimensions = 4;

}  // namespace

double PathRandom::get(uint32_t bounce, uint32_t dimension) const {
  return hashed_uniform(seed_, path_, bounce * per_bounce_ + dimension);
}

// The path's current end and how light arriving there reaches the path's start: through the
// first vertex's two lobes (their BRDF x cos / pdf), times the throughput of the rest.
struct PathTransport::State {
  Vertex vertex;
  glm::dvec3 view;  // unit, from the end back along the path
  glm::dvec3 diffuse{0.0}, specular{0.0};
  glm::dvec3 throughput{1.0};
  bool at_first = true;  // the end is the camera's visible surface

  // Light `c` arriving at the end (after the first vertex's lobes are known).
  void add(PathValue& out, bool scene_light, glm::dvec3 c) const {
    if (at_first && scene_light) {
      out.direct += (diffuse + specular) * c;
    } else {
      out.indirect_diffuse += diffuse * throughput * c;
      out.specular += specular * throughput * c;
    }
  }
};

PathTransport::PathTransport(const PathScene& scene, uint32_t max_bounces, uint32_t russian_roulette_after)
    : scene_(scene), max_bounces_(max_bounces), russian_roulette_after_(russian_roulette_after) {}

uint32_t PathTransport::dimensions_per_bounce() const {
  return kLightDimensions + 2 * uint32_t(scene_.lights().count()) + 2;
}

bool PathTransport::visible(glm::dvec3 position, glm::dvec3 geometric, glm::dvec3 direction, double distance) const {
  if (!(glm::dot(direction, geometric) > 0.0)) return false;
  const glm::vec3 origin = offset_ray_origin(glm::vec3(position), glm::vec3(geometric));
  const float t_max = std::isinf(distance) ? std::numeric_limits<float>::infinity() : float(distance);
  return !scene_.rays().occluded(origin, glm::vec3(direction), t_max);
}

double PathTransport::brdf_pdf(const State& s, glm::dvec3 l) const {
  const double p_specular = specular_lobe_probability(s.vertex.brdf, s.view);
  return p_specular * specular_pdf(s.vertex.brdf, s.view, l) + (1.0 - p_specular) * diffuse_pdf(s.vertex.brdf, l);
}

// Light `weight` arriving at the end from direction l, reflected toward the path's start.
void PathTransport::reflect(State& s, glm::dvec3 l, glm::dvec3 weight, bool scene_light, PathValue& out) const {
  const BrdfCosine f = evaluate_brdf(s.vertex.brdf, s.view, l);
  if (s.at_first) {
    if (scene_light)
      out.direct += f.sum() * weight;
    else
      out.indirect_diffuse += f.diffuse * weight, out.specular += f.specular * weight;
  } else {
    s.add(out, scene_light, f.sum() * weight);
  }
}

// Next-event estimation of every light of PathLights at the end, each weighed against the BRDF's
// density by MIS when a BRDF sample follows (`with_mis`).
void PathTransport::sample_lights(State& s, uint32_t bounce, const PathRandom& random, PathValue& out,
                                  bool with_mis) const {
  const Vertex& v = s.vertex;
  const PathLights& lights = scene_.lights();
  for (size_t i = 0; i < lights.count(); ++i) {
    const std::optional<LightSample> ls =
        lights.sample(i, v.position, random.pair(bounce, kLightDimensions + 2 * uint32_t(i)));
    if (!ls || !visible(v.position, v.geometric, ls->direction, ls->distance)) continue;
    const double mis = with_mis && ls->pdf > 0.0 ? power_heuristic(ls->pdf, brdf_pdf(s, ls->direction)) : 1.0;
    reflect(s, ls->direction, ls->weight * mis, lights.is_scene_light(i), out);
  }
}

struct PathTransport::BrdfSample {
  glm::dvec3 l{0.0};
  double pdf = 0.0;  // 0: none (below the geometric surface, or the BRDF is 0 there)
  BrdfCosine f;
};

// A direction from the end's BRDF (the lobe by specular_lobe_probability()), its mixture density
// and the BRDF's value there.
PathTransport::BrdfSample PathTransport::sample_brdf(const State& s, uint32_t bounce, const PathRandom& random) const {
  const BrdfSurface& brdf = s.vertex.brdf;
  BrdfSample b;
  b.l = random.get(bounce, 0) < specular_lobe_probability(brdf, s.view)
            ? sample_specular(brdf, s.view, random.pair(bounce, 1))
            : sample_diffuse(brdf, random.pair(bounce, 1));
  if (!(glm::dot(b.l, s.vertex.geometric) > 0.0)) return b;
  b.f = evaluate_brdf(brdf, s.view, b.l);
  if (b.f.sum() != glm::dvec3(0.0)) b.pdf = brdf_pdf(s, b.l);
  return b;
}

// Next-event estimation at the end, then the BRDF's own sample and the segment it starts.
bool PathTransport::step(State& s, uint32_t bounce, const PathRandom& random, PathValue& out) const {
  const Vertex& v = s.vertex;
  sample_lights(s, bounce, random, out, true);
  if (const EnvironmentMap* env = scene_.environment()) {
    const auto es = env->sample(random.pair(bounce, kLightDimensions + 2 * uint32_t(scene_.lights().count())));
    if (es && visible(v.position, v.geometric, es->direction, kInfinity))
      reflect(s, es->direction, es->radiance / es->pdf * power_heuristic(es->pdf, brdf_pdf(s, es->direction)), false,
              out);
  }

  const BrdfSample b = sample_brdf(s, bounce, random);
  if (!(b.pdf > 0.0)) return false;  // below the surface, or nothing reflected: absorbed
  if (s.at_first)
    s.diffuse = b.f.diffuse / b.pdf, s.specular = b.f.specular / b.pdf;
  else
    s.throughput *= b.f.sum() / b.pdf;
  const glm::dvec3 origin(offset_ray_origin(glm::vec3(v.position), glm::vec3(v.geometric)));
  const bool more = segment(s, origin, b.l, b.pdf, bounce, random, out, nullptr);
  s.at_first = false;
  return more;
}

// The ray from `origin` along l: the lights it crosses and the environment or surface it ends
// at. `pdf` is the density l was drawn with by a BRDF whose vertex also ran next-event
// estimation; 0 for a probe's ray, whose start ran none: then nothing is weighted, and the
// scene's lights it crosses are left out (they are direct light to whatever the probe lights).
bool PathTransport::segment(State& s, glm::dvec3 origin, glm::dvec3 l, double pdf, uint32_t bounce,
                            const PathRandom& random, PathValue& out, ProbeRay* first_hit) const {
  const std::optional<RayHit> hit =
      scene_.rays().intersect(glm::vec3(origin), glm::vec3(l), std::numeric_limits<float>::infinity());
  const double t = hit ? double(hit->distance) : kInfinity;
  const PathLights& lights = scene_.lights();
  lights.each_crossed(origin, l, t, [&](size_t i, const LightCrossing& c) {
    const bool scene_light = lights.is_scene_light(i);
    if (pdf > 0.0)
      s.add(out, scene_light, c.radiance * power_heuristic(pdf, c.pdf));
    else if (!scene_light)
      s.add(out, false, c.radiance);
  });
  if (first_hit) *first_hit = ProbeRay{{}, t, hit && glm::dot(glm::dvec3(hit->normal), l) > 0.0};
  if (!hit) {
    if (const EnvironmentMap* env = scene_.environment())
      s.add(out, false, env->radiance(l) * (pdf > 0.0 ? power_heuristic(pdf, env->pdf(l)) : 1.0));
    return false;
  }
  s.vertex = make_vertex(scene_, *hit, origin + l * t, l);
  s.view = -l;
  s.add(out, false, s.vertex.emission);  // emissive surfaces are not light-sampled: counted in full
  if (pdf > 0.0 && bounce + 1 >= russian_roulette_after_) {
    const glm::dvec3 total = (s.diffuse + s.specular) * s.throughput;
    const double survive = std::min(std::max({total.r, total.g, total.b}), 0.95);
    if (!(random.get(bounce, 3) < survive)) return false;
    s.throughput /= survive;
  }
  return true;
}

PathValue PathTransport::camera_path(glm::dvec3 eye, glm::dvec3 direction, bool cull_backfaces,
                                     const PathRandom& random) const {
  PathValue out;
  const std::optional<CameraHit> hit = first_camera_hit(scene_.rays(), eye, direction, cull_backfaces);
  if (!hit) {  // the environment, with the sky's sun: what the camera sees without a reflection
    if (const EnvironmentMap* env = scene_.environment()) out.emission += env->radiance(direction);
    scene_.lights().each_crossed(eye, direction, kInfinity, [&](size_t i, const LightCrossing& c) {
      if (!scene_.lights().is_scene_light(i)) out.emission += c.radiance;
    });
    return out;
  }
  State s{make_vertex(scene_, hit->hit, hit->position, direction), -direction};
  out.emission = s.vertex.emission;
  for (uint32_t bounce = 0; bounce < max_bounces_; ++bounce)
    if (!step(s, bounce, random, out)) break;
  return out;
}

ProbeRay PathTransport::probe_ray(glm::dvec3 origin, glm::dvec3 direction, const PathRandom& random) const {
  PathValue out;
  ProbeRay ray;
  State s{};
  s.at_first = false;
  s.diffuse = glm::dvec3(1.0);  // all that arrives lands in indirect_diffuse
  if (segment(s, origin, direction, 0.0, 0, random, out, &ray))
    for (uint32_t bounce = 0; bounce < max_bounces_; ++bounce)
      if (!step(s, bounce, random, out)) break;
  ray.radiance = out.indirect_diffuse;
  return ray;
}

ProbeHit PathTransport::probe_hit(glm::dvec3 origin, glm::dvec3 direction, const PathRandom& random) const {
  PathValue out;
  ProbeHit h;
  State s{};
  s.at_first = false;
  s.diffuse = glm::dvec3(1.0);  // as probe_ray()
  if (segment(s, origin, direction, 0.0, 0, random, out, &h.ray)) {
    sample_lights(s, 0, random, out, false);
    h.surface = VisibleSurface{s.vertex.position, s.vertex.brdf.normal, diffuse_reflectance(s.vertex.brdf, -direction)};
    const BrdfSample b = sample_brdf(s, 0, random);
    if (b.pdf > 0.0) h.albedo = b.f.sum() / b.pdf;
  }
  h.ray.radiance = out.indirect_diffuse;
  return h;
}

std::optional<VisibleSurface> PathTransport::visible_surface(glm::dvec3 eye, glm::dvec3 direction,
                                                             bool cull_backfaces) const {
  const std::optional<CameraHit> hit = first_camera_hit(scene_.rays(), eye, direction, cull_backfaces);
  if (!hit) return std::nullopt;
  const Vertex v = make_vertex(scene_, hit->hit, hit->position, direction);
  return VisibleSurface{v.position, v.brdf.normal, diffuse_reflectance(v.brdf, -direction)};
}

}  // namespace lg
