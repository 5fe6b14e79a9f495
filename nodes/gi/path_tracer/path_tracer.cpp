#include "nodes/gi/path_tracer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "nodes/gi/path_tracer/microfacet_brdf.h"
#include "nodes/raytrace/camera_hit.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_offset.h"

namespace lg {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The AOVs of one path.
struct PathValue {
  glm::dvec3 emission{0.0}, direct{0.0}, indirect_diffuse{0.0}, specular{0.0};
  glm::dvec3 aov(size_t i) const {
    switch (ReferenceAov(i)) {
      case ReferenceAov::radiance:
        return emission + direct + indirect_diffuse + specular;
      case ReferenceAov::emission:
        return emission;
      case ReferenceAov::direct:
        return direct;
      case ReferenceAov::indirect_diffuse:
        return indirect_diffuse;
      case ReferenceAov::specular:
        return specular;
    }
    return glm::dvec3(0.0);
  }
};

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
  const SurfaceMaterial material = sample_material(view, view.draws[attributes.draw], attributes.uv);
  glm::dvec3 geometric(hit.normal);
  if (glm::dot(geometric, ray_direction) > 0.0) geometric = -geometric;
  const glm::dvec3 shading = glm::dot(attributes.normal, geometric) < 0.0 ? -attributes.normal : attributes.normal;
  return Vertex{position, geometric, make_brdf_surface(shading, material), material.emissive};
}

// One path's random numbers: a hash of (seed, path, dimension), dimensions laid out per bounce.
class PathRandom {
 public:
  PathRandom(uint64_t seed, uint64_t path, uint32_t per_bounce) : seed_(seed), path_(path), per_bounce_(per_bounce) {}
  double get(uint32_t bounce, uint32_t dimension) const {
    return hashed_uniform(seed_, path_, bounce * per_bounce_ + dimension);
  }
  glm::dvec2 get2(uint32_t bounce, uint32_t dimension) const {
    return {get(bounce, dimension), get(bounce, dimension + 1)};
  }

 private:
  uint64_t seed_, path_;
  uint32_t per_bounce_;
};

class Integrator {
 public:
  Integrator(const PathScene& scene, const PathTracerOptions& options) : scene_(scene), options_(options) {}

  // Dimensions a bounce uses: lobe choice, BRDF direction (2), roulette, then 2 a light and 2
  // for the environment.
  uint32_t dimensions_per_bounce() const { return 4 + 2 * uint32_t(scene_.lights().count()) + 2; }

  PathValue trace(glm::dvec3 eye, glm::dvec3 direction, const PathRandom& random) const {
    PathValue out;
    const std::optional<CameraHit> hit = first_camera_hit(scene_.rays(), eye, direction, options_.cull_backfaces);
    if (!hit) {  // the environment, with the sun's disk: all of it "emission" the camera sees
      if (const EnvironmentMap* env = scene_.environment()) out.emission += env->radiance(direction);
      scene_.lights().each_crossed(eye, direction, kInfinity, [&](size_t i, const LightCrossing& c) {
        if (!scene_.lights().is_scene_light(i)) out.emission += c.radiance;
      });
      return out;
    }
    Vertex vertex = make_vertex(scene_, hit->hit, hit->position, direction);
    out.emission = vertex.emission;
    glm::dvec3 view = -direction;
    // Weights of the first vertex's lobes for light that arrives there other than by NEE, and the
    // throughput of the rest of the path.
    glm::dvec3 first_diffuse(0.0), first_specular(0.0), throughput(1.0);
    // Light `c` arriving at the path's current end, seen through the first vertex's lobes
    // `diffuse` and `specular` (at the first vertex itself: the BRDF's own lobes).
    auto add = [&](bool first, bool scene_light, glm::dvec3 diffuse, glm::dvec3 specular, glm::dvec3 c) {
      if (first && scene_light) {
        out.direct += (diffuse + specular) * c;
      } else {
        out.indirect_diffuse += diffuse * c;
        out.specular += specular * c;
      }
    };
    for (uint32_t bounce = 0; bounce < options_.max_bounces; ++bounce) {
      const bool first = bounce == 0;
      const BrdfSurface& s = vertex.brdf;
      const double p_specular = specular_lobe_probability(s, view);
      auto brdf_pdf = [&](glm::dvec3 l) {
        return p_specular * specular_pdf(s, view, l) + (1.0 - p_specular) * diffuse_pdf(s, l);
      };
      // What reaches the first vertex through this one, per unit of the BRDF-weighted light.
      auto through = [&](const BrdfCosine& f, glm::dvec3 weight, bool scene_light) {
        if (first)
          add(true, scene_light, f.diffuse, f.specular, weight);
        else
          add(false, scene_light, first_diffuse, first_specular, throughput * f.sum() * weight);
      };

      // Next-event estimation: every light, then the environment.
      for (size_t i = 0; i < scene_.lights().count(); ++i) {
        const std::optional<LightSample> ls =
            scene_.lights().sample(i, vertex.position, random.get2(bounce, 4 + 2 * uint32_t(i)));
        if (!ls || !visible(vertex, ls->direction, ls->distance)) continue;
        const BrdfCosine f = evaluate_brdf(s, view, ls->direction);
        const double mis = ls->pdf > 0.0 ? power_heuristic(ls->pdf, brdf_pdf(ls->direction)) : 1.0;
        through(f, ls->weight * mis, scene_.lights().is_scene_light(i));
      }
      const EnvironmentMap* env = scene_.environment();
      if (env) {
        const uint32_t d = 4 + 2 * uint32_t(scene_.lights().count());
        if (auto es = env->sample(random.get2(bounce, d)); es && visible(vertex, es->direction, kInfinity)) {
          const BrdfCosine f = evaluate_brdf(s, view, es->direction);
          through(f, es->radiance / es->pdf * power_heuristic(es->pdf, brdf_pdf(es->direction)), false);
        }
      }

      // The BRDF's own sample, which also meets what NEE sampled (weighted by MIS).
      const glm::dvec3 l = random.get(bounce, 0) < p_specular ? sample_specular(s, view, random.get2(bounce, 1))
                                                              : sample_diffuse(s, random.get2(bounce, 1));
      if (!(glm::dot(l, vertex.geometric) > 0.0)) break;  // below the surface: absorbed
      const double pdf = brdf_pdf(l);
      const BrdfCosine f = evaluate_brdf(s, view, l);
      if (!(pdf > 0.0) || f.sum() == glm::dvec3(0.0)) break;
      if (first)
        first_diffuse = f.diffuse / pdf, first_specular = f.specular / pdf;
      else
        throughput *= f.sum() / pdf;

      const glm::vec3 origin = offset_ray_origin(glm::vec3(vertex.position), glm::vec3(vertex.geometric));
      const std::optional<RayHit> next =
          scene_.rays().intersect(origin, glm::vec3(l), std::numeric_limits<float>::infinity());
      const double t_hit = next ? double(next->distance) : kInfinity;
      scene_.lights().each_crossed(glm::dvec3(origin), l, t_hit, [&](size_t i, const LightCrossing& c) {
        add(first, scene_.lights().is_scene_light(i), first_diffuse, first_specular,
            throughput * c.radiance * power_heuristic(pdf, c.pdf));
      });
      if (!next) {
        if (env)
          add(first, false, first_diffuse, first_specular,
              throughput * env->radiance(l) * power_heuristic(pdf, env->pdf(l)));
        break;
      }
      vertex = make_vertex(scene_, *next, glm::dvec3(origin) + l * t_hit, l);
      view = -l;
      // Emissive surfaces are not light-sampled: what the BRDF sample meets counts in full.
      add(false, false, first_diffuse, first_specular, throughput * vertex.emission);

      if (bounce + 1 >= options_.russian_roulette_after) {
        const glm::dvec3 total = (first_diffuse + first_specular) * throughput;
        const double survive = std::min(std::max({total.r, total.g, total.b}), 0.95);
        if (!(random.get(bounce, 3) < survive)) break;
        throughput /= survive;
      }
    }
    return out;
  }

 private:
  bool visible(const Vertex& v, glm::dvec3 direction, double distance) const {
    if (!(glm::dot(direction, v.geometric) > 0.0)) return false;
    const glm::vec3 origin = offset_ray_origin(glm::vec3(v.position), glm::vec3(v.geometric));
    const float t_max = std::isinf(distance) ? std::numeric_limits<float>::infinity() : float(distance);
    return !scene_.rays().occluded(origin, glm::vec3(direction), t_max);
  }

  const PathScene& scene_;
  const PathTracerOptions& options_;
};

bool finite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

const char* reference_aov_name(ReferenceAov aov) {
  switch (aov) {
    case ReferenceAov::radiance:
      return "radiance";
    case ReferenceAov::emission:
      return "emission";
    case ReferenceAov::direct:
      return "direct";
    case ReferenceAov::indirect_diffuse:
      return "indirect_diffuse";
    case ReferenceAov::specular:
      return "specular";
  }
  return "?";
}

std::optional<ReferenceAov> parse_reference_aov(const std::string& name) {
  for (size_t i = 0; i < kReferenceAovCount; ++i)
    if (name == reference_aov_name(ReferenceAov(i))) return ReferenceAov(i);
  return std::nullopt;
}

ReferenceImage trace_reference(const PathScene& scene, const PathTracerOptions& options,
                               const std::function<void(size_t)>& progress) {
  ReferenceImage out;
  out.width = options.width, out.height = options.height;
  out.row_begin = std::min(options.row_begin, options.height);
  out.row_end = options.row_end == 0 ? options.height : std::min(options.row_end, options.height);
  out.row_end = std::max(out.row_end, out.row_begin);
  for (size_t a = 0; a < kReferenceAovCount; ++a) {
    out.mean[a].assign(out.pixel_count(), glm::vec3(0.0f));
    out.standard_error[a].assign(out.pixel_count(), glm::vec3(0.0f));
  }
  if (out.pixel_count() == 0) return out;
  const CameraPixels pixels(scene.view().camera, options.width, options.height);
  const Integrator integrator(scene, options);
  const uint32_t n = std::max(options.samples_per_pixel, 1u);
  std::vector<uint32_t> dropped(out.pixel_count(), 0);
  auto trace_pixel = [&](size_t i) {
    const uint32_t x = uint32_t(i % options.width), y = out.row_begin + uint32_t(i / options.width);
    const uint64_t pixel = uint64_t(y) * options.width + x;
    const glm::dvec3 direction = pixels.ray_direction(x, y);
    std::array<glm::dvec3, kReferenceAovCount> sum{}, sum_squares{};
    for (uint32_t k = 0; k < n; ++k) {
      const PathRandom random(options.seed, pixel * n + k, integrator.dimensions_per_bounce());
      const PathValue value = integrator.trace(pixels.eye(), direction, random);
      std::array<glm::dvec3, kReferenceAovCount> v;
      bool ok = true;
      for (size_t a = 0; a < kReferenceAovCount; ++a) ok = ok && finite(v[a] = value.aov(a));
      if (!ok) {
        ++dropped[i];
        continue;
      }
      for (size_t a = 0; a < kReferenceAovCount; ++a) sum[a] += v[a], sum_squares[a] += v[a] * v[a];
    }
    for (size_t a = 0; a < kReferenceAovCount; ++a) {
      const glm::dvec3 mean = sum[a] / double(n);
      // The unbiased variance of one path's value, over n for the mean's.
      const glm::dvec3 variance =
          n > 1 ? glm::max(sum_squares[a] / double(n) - mean * mean, 0.0) * (double(n) / (n - 1)) : glm::dvec3(0.0);
      out.mean[a][i] = glm::vec3(mean);
      out.standard_error[a][i] = glm::vec3(glm::sqrt(variance / double(n)));
    }
  };
  if (progress)
    parallel_for_with_progress(out.pixel_count(), trace_pixel, progress);
  else
    parallel_for(out.pixel_count(), trace_pixel);
  for (uint32_t d : dropped) out.non_finite_samples += d;
  return out;
}

}  // namespace lg
