// lighting.ibl's pass on lavapipe against its formulas in double precision, on a random
// G-buffer (fixed seeds) with random SH irradiance of order 4, a prefiltered map whose mips are
// distinct constants (so the roughness-to-mip lookup is checked), the DFG reference table,
// direct light and AO (Lagarde's specular occlusion); with random bent normals and visibility
// cones as well (the cone folded into the SH lobe, cone-cone specular occlusion, multi-bounce),
// with SH and with an irradiance map; also with every optional input unlinked; a white furnace;
// and the sky behind pixels with no surface. Tolerance 6e-3 of the pixel's largest channel
// (measured 1.7e-3 with AO, 1.7e-3 with cones and SH, 3.2e-3 with cones and the map, 2.8e-3
// with the map alone; 4.8e-3 on a rough metal in an earlier draw): rgba16f output (4.9e-4),
// lavapipe's mip fraction of 4 bits (mipmapPrecisionBits; mips 10% apart: up to 3.1e-3 of the
// specular), 8-bit filter weights across the DFG table's texels. The cone formulas in float add
// little: the cap intersection's atan2 form keeps nearly touching caps to about 1e-6 sr.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <iostream>
#include <numbers>
#include <random>

#include "nodes/common/camera_constants.h"
#include "nodes/common/gbuffer_normal.h"
#include "nodes/env/brdf_lut/dfg_reference.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/lighting/ibl/ibl_kernel.h"
#include "nodes/lighting/ibl/ibl_occlusion.h"
#include "nodes/lighting/ibl/ibl_reference.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr uint32_t kSize = 16;  // frame
constexpr uint32_t kLut = 32;
constexpr uint32_t kSpecularMips = 4;  // 8^2 down to 1^2
constexpr double kMipStep = 0.1;       // mip m holds base * (1 + 0.1 m)

// What an image of `format` holds for `rgba` (the GPU reads exactly that).
std::vector<float> stored(VkFormat format, std::vector<float> rgba) {
  const FormatInfo& info = format_info(format);
  std::vector<std::byte> bytes(rgba.size() / 4 * info.bytes_per_texel);
  encode_texels(info, rgba, bytes);
  decode_texels(info, bytes, rgba);
  return rgba;
}

// Which inputs a run links: `ao` (SH, direct, AO, specular occlusion from AO), `cones` (those and
// bent normals with visibility cones, and multi-bounce), `map` (an irradiance map, nothing
// optional), `map_cones` (the map and cones without AO: the cone's own visibility, multi-bounce).
enum class Inputs { ao, cones, map, map_cones };

struct Scene {
  CameraConstants camera;
  std::vector<float> depth, normal, albedo, material, direct, ao;
  std::vector<float> bent;     // rgba8_snorm as stored: bent normal, cone cosine
  std::vector<glm::dvec3> sh;  // irradiance coefficients, order 4
  glm::dvec3 specular_base{1.0, 0.8, 0.6};
  std::vector<float> lut;  // rg16f as stored
};

Scene make_scene(uint64_t seed, bool furnace) {
  Scene s;
  const glm::mat4 view = glm::lookAt(glm::vec3(0.3f, 0.2f, 3.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  CameraView cam;
  cam.view = view;
  cam.projection = glm::perspectiveRH_ZO(1.0f, 1.0f, 0.5f, 20.0f);
  cam.position = glm::vec3(0.3f, 0.2f, 3.0f);
  s.camera = camera_constants(cam, kSize, kSize);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  for (uint32_t t = 0; t < kSize * kSize; ++t) {
    const bool sky = t % 7 == 3;
    s.depth.insert(s.depth.end(), {sky ? 0.0f : float(0.2 + 0.7 * unit(rng)), 0, 0, 1});
    const glm::dvec3 n = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const glm::dvec3 stored = encode_gbuffer_normal(n);
    s.normal.insert(s.normal.end(), {float(stored.x), float(stored.y), float(stored.z), 1});
    for (int c = 0; c < 3; ++c) s.albedo.push_back(furnace ? 1.0f : float(0.05 + 0.95 * unit(rng)));
    s.albedo.push_back(1);
    s.material.insert(s.material.end(), {float(unit(rng)), furnace ? 1.0f : float(unit(rng)), 0, 1});
    for (int c = 0; c < 3; ++c) s.direct.push_back(float(unit(rng)));
    s.direct.push_back(1);
    s.ao.insert(s.ao.end(), {float(0.2 + 0.8 * unit(rng)), 0, 0, 1});
    // A bent normal within about 40 degrees of the normal and a cone of 25 to 90 degrees; every
    // eleventh texel has none written (the shader's open hemisphere).
    const glm::dvec3 bent = glm::normalize(n + 0.4 * glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const bool none = t % 11 == 5;
    s.bent.insert(s.bent.end(), {none ? 0.0f : float(bent.x), none ? 0.0f : float(bent.y), none ? 0.0f : float(bent.z),
                                 none ? 0.0f : float(0.9 * unit(rng))});
  }
  s.bent = stored(VK_FORMAT_R8G8B8A8_SNORM, s.bent);
  s.depth = stored(VK_FORMAT_R32G32B32A32_SFLOAT, s.depth);
  s.normal = stored(VK_FORMAT_A2B10G10R10_UNORM_PACK32, s.normal);
  s.albedo = stored(VK_FORMAT_R8G8B8A8_SRGB, s.albedo);
  s.material = stored(VK_FORMAT_R8G8_UNORM, s.material);
  s.direct = stored(VK_FORMAT_R16G16B16A16_SFLOAT, s.direct);
  s.ao = stored(VK_FORMAT_R8_UNORM, s.ao);
  // Order 4, as irradiance: band 3 is 0 (the cosine lobe has none).
  s.sh.assign(25, glm::dvec3(0.0));
  s.sh[0] = glm::dvec3(6.0, 5.0, 4.0);
  for (int k = 1; k < 25; ++k)
    if (k < 9 || k >= 16) s.sh[k] = glm::dvec3(normal(rng), normal(rng), normal(rng)) * (k < 9 ? 0.5 : 0.1);
  if (furnace) s.specular_base = glm::dvec3(1.5, 1.5, 1.5);
  for (uint32_t j = 0; j < kLut; ++j)
    for (uint32_t i = 0; i < kLut; ++i) {
      const glm::dvec2 d = dfg_reference(std::max(double(i) / (kLut - 1), 1e-3), double(j) / (kLut - 1), 32);
      s.lut.insert(s.lut.end(), {float(d.x), float(d.y), 0, 1});
    }
  s.lut = stored(VK_FORMAT_R16G16_SFLOAT, s.lut);
  return s;
}

glm::dvec3 texel3(const std::vector<float>& v, uint32_t t) {
  return {v[4 * t], v[4 * t + 1], v[4 * t + 2]};
}

// Bilinear on the stored table at the shader's coordinates, clamped at the edges.
glm::dvec2 lut_lookup(const std::vector<float>& lut, double n_dot_v, double roughness) {
  const double x = std::clamp(n_dot_v * (kLut - 1), 0.0, kLut - 1.0),
               y = std::clamp(roughness * (kLut - 1), 0.0, kLut - 1.0);
  const uint32_t x0 = std::min(uint32_t(x), kLut - 2), y0 = std::min(uint32_t(y), kLut - 2);
  const double fx = x - x0, fy = y - y0;
  auto at = [&](uint32_t i, uint32_t j) { return glm::dvec2(lut[(j * kLut + i) * 4], lut[(j * kLut + i) * 4 + 1]); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

glm::dvec3 world_position(const CameraConstants& c, uint32_t x, uint32_t y, double depth) {
  const glm::dvec4 ndc((x + 0.5) / kSize * 2 - 1, (y + 0.5) / kSize * 2 - 1, depth, 1);
  const glm::dvec4 p = glm::dmat4(c.inverse_view_projection) * ndc;
  return glm::dvec3(p) / p.w;
}

class IblGpuTest : public GpuTest {
 protected:
  Image image2d(const char* name, VkFormat format, uint32_t size, const std::vector<float>& rgba) {
    Image image = Image::dedicated(context(), {.name = name, .format = format, .width = size, .height = size});
    upload_image(submitter(), image, rgba, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    return image;
  }

  // Runs the pass with `inputs`; the irradiance map holds E / pi = sh[0] Y00 / pi (constant).
  std::vector<float> run(const Scene& s, Inputs inputs) {
    const bool full = inputs == Inputs::ao || inputs == Inputs::cones;
    const bool cones = inputs == Inputs::cones || inputs == Inputs::map_cones;
    Buffer camera = Buffer::dedicated(context(), {.name = "camera", .size = sizeof(CameraConstants)});
    upload_buffer(submitter(), camera, std::as_bytes(std::span(&s.camera, 1)));
    Image depth = image2d("depth", VK_FORMAT_R32G32B32A32_SFLOAT, kSize, s.depth);
    Image normal = image2d("normal", VK_FORMAT_A2B10G10R10_UNORM_PACK32, kSize, s.normal);
    Image albedo = image2d("albedo", VK_FORMAT_R8G8B8A8_SRGB, kSize, s.albedo);
    Image material = image2d("material", VK_FORMAT_R8G8_UNORM, kSize, s.material);
    Image direct = image2d("direct", VK_FORMAT_R16G16B16A16_SFLOAT, kSize, s.direct);
    Image ao = image2d("ao", VK_FORMAT_R8_UNORM, kSize, s.ao);
    Image bent = image2d("bent normals", VK_FORMAT_R8G8B8A8_SNORM, kSize, s.bent);
    Image lut = image2d("dfg", VK_FORMAT_R16G16_SFLOAT, kLut, s.lut);
    std::vector<glm::vec4> sh4;
    for (const glm::dvec3& c : s.sh) sh4.emplace_back(glm::vec3(c), 0.0f);
    Buffer sh = Buffer::dedicated(context(), {.name = "sh", .size = sh4.size() * 16});
    upload_buffer(submitter(), sh, std::as_bytes(std::span(sh4)));
    std::vector<CubeImage> mips;
    for (uint32_t m = 0; m < kSpecularMips; ++m) {
      CubeImage mip(8 >> m);
      for (glm::dvec4& t : mip.texels) t = glm::dvec4(s.specular_base * (1 + kMipStep * m), 1.0);
      mips.push_back(mip);
    }
    Image specular = make_cube(context(), "specular", 8, kSpecularMips);
    upload_cube(submitter(), specular, mips, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    CubeImage e_over_pi(2);
    for (glm::dvec4& t : e_over_pi.texels)
      t = glm::dvec4(s.sh[0] * (0.5 / std::sqrt(std::numbers::pi)) / std::numbers::pi, 1);
    Image irradiance = make_cube(context(), "irradiance", 2, 1);
    upload_cube(submitter(), irradiance, {e_over_pi}, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    Image color = Image::dedicated(
        context(), {.name = "color", .format = VK_FORMAT_R16G16B16A16_SFLOAT, .width = kSize, .height = kSize});

    IblInputs in;
    in.camera = camera.handle();
    in.depth = &depth, in.normal = &normal, in.albedo = &albedo, in.material = &material;
    in.specular = &specular, in.brdf_lut = &lut, in.color = &color;
    if (full)
      in.direct = &direct, in.sh = &sh, in.ao = &ao;
    else
      in.irradiance = &irradiance;
    if (cones) in.bent_normals = &bent;
    const IblSettings settings{
        .diffuse_from_sh = full, .intensity = 1.0f, .specular_occlusion = full || cones, .multi_bounce = cones};
    IblFallbacks fallbacks(context());
    Sampler linear(context(), {.filter = Filter::linear}), nearest(context(), {.filter = Filter::nearest});
    submitter().run([&](VkCommandBuffer cmd) {
      image_barrier(cmd, color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      record_ibl(context(), pipelines(), cmd, "ibl/shade", settings, in, fallbacks, linear.handle(), nearest.handle());
      memory_barrier(cmd);
    });
    return read_image(submitter(), color, VK_IMAGE_LAYOUT_GENERAL);
  }

  glm::dvec3 expected(const Scene& s, uint32_t x, uint32_t y, Inputs inputs) {
    const bool full = inputs == Inputs::ao || inputs == Inputs::cones;
    const uint32_t t = y * kSize + x;
    const glm::dvec3 eye(s.camera.position);
    const glm::dvec3 direct = full ? texel3(s.direct, t) : glm::dvec3(0.0);
    if (s.depth[4 * t] <= 0) return direct + s.specular_base;
    const glm::dvec3 p = world_position(s.camera, x, y, s.depth[4 * t]);
    const glm::dvec3 n = decode_gbuffer_normal(&s.normal[4 * t]);
    const glm::dvec3 v = glm::normalize(eye - p);
    const IblSurface surface{texel3(s.albedo, t), s.material[4 * t], s.material[4 * t + 1]};
    const double n_dot_v = std::clamp(glm::dot(n, v), 1e-4, 1.0);
    const double lod = surface.roughness * (kSpecularMips - 1);
    const glm::dvec3 prefiltered = s.specular_base * (1 + kMipStep * lod);
    const glm::dvec2 ab = lut_lookup(s.lut, n_dot_v, surface.roughness);
    const glm::dvec3 map_irradiance = s.sh[0] * (0.5 / std::sqrt(std::numbers::pi));
    if (inputs == Inputs::map) return ibl_shade_reference(surface, map_irradiance, prefiltered, ab);
    const glm::dvec3 diffuse_unoccluded = ibl_shade_reference(surface, glm::dvec3(1.0), glm::dvec3(0.0), ab);
    const glm::dvec3 specular = ibl_shade_reference(surface, glm::dvec3(0.0), prefiltered, ab);
    if (inputs == Inputs::ao) {
      const double ao = s.ao[4 * t];
      return direct + diffuse_unoccluded * glm::max(evaluate_sh(s.sh, n), glm::dvec3(0.0)) * ao +
             specular * specular_occlusion_from_ao(n_dot_v, ao, surface.roughness);
    }
    const glm::dvec3 written = texel3(s.bent, t);
    const bool has_cone = glm::dot(written, written) > 1e-6;
    const glm::dvec3 bent = has_cone ? glm::normalize(written) : n;
    const double cone_cos = has_cone ? std::clamp(double(s.bent[4 * t + 3]), 0.0, 1.0) : 0.0;
    const glm::dvec3 diffuse_color = surface.albedo * (1 - surface.metalness);
    // The AO input where linked, else the cone's own visibility.
    const double visibility = full ? s.ao[4 * t] : 1 - cone_cos * cone_cos;
    glm::dvec3 occlusion;
    for (int c = 0; c < 3; ++c) occlusion[c] = multi_bounce_occlusion(visibility, diffuse_color[c]);
    const glm::dvec3 irradiance = full ? cone_lobe_irradiance(s.sh, n, bent, cone_cos, 1.0) : map_irradiance;
    const glm::dvec3 r = glm::reflect(-v, n);
    return direct + diffuse_unoccluded * irradiance * occlusion +
           specular * specular_occlusion_from_cone(n, r, bent, cone_cos, surface.roughness);
  }

  double max_relative_error(const Scene& s, Inputs inputs) {
    const std::vector<float> gpu = run(s, inputs);
    double worst = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const glm::dvec3 e = expected(s, x, y, inputs), g = texel3(gpu, y * kSize + x);
        const double scale = std::max({e.x, e.y, e.z});
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(g[c] - e[c]) / scale);
      }
    return worst;
  }
};

TEST_F(IblGpuTest, MatchesTheFormulasWithAmbientOcclusion) {
  const double err = max_relative_error(make_scene(70, false), Inputs::ao);
  std::cout << "SH, direct, AO and specular occlusion from AO: max relative error " << err << "\n";
  EXPECT_LE(err, 6e-3);
}

TEST_F(IblGpuTest, MatchesTheFormulasWithVisibilityCones) {
  const double err = max_relative_error(make_scene(73, false), Inputs::cones);
  std::cout << "SH, direct, AO, cones, cone-cone specular occlusion, multi-bounce: max relative error " << err << "\n";
  EXPECT_LE(err, 6e-3);
}

TEST_F(IblGpuTest, MatchesTheFormulasWithAnIrradianceMapAndCones) {
  const double err = max_relative_error(make_scene(74, false), Inputs::map_cones);
  std::cout << "irradiance map, cones without AO: max relative error " << err << "\n";
  EXPECT_LE(err, 6e-3);
}

TEST_F(IblGpuTest, MatchesTheFormulasWithAnIrradianceMapAndNoOptionalInputs) {
  const double err = max_relative_error(make_scene(71, false), Inputs::map);
  std::cout << "irradiance map, nothing optional: max relative error " << err << "\n";
  EXPECT_LE(err, 6e-3);
}

// Albedo 1 and metal: F0 = 1, and the energy compensation returns what single scattering lost,
// so a constant environment comes back whole at every roughness and angle (plus diffuse 0).
TEST_F(IblGpuTest, WhiteFurnaceReflectsTheEnvironment) {
  Scene s = make_scene(72, true);
  const std::vector<float> gpu = run(s, Inputs::map);
  double worst = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const uint32_t t = y * kSize + x;
      const double lod = s.depth[4 * t] > 0 ? s.material[4 * t] * (kSpecularMips - 1) : 0.0;  // sky: mip 0
      worst = std::max(worst, std::abs(gpu[4 * (y * kSize + x)] / (1.5 * (1 + kMipStep * lod)) - 1));
    }
  std::cout << "white furnace: max relative error " << worst << "\n";
  EXPECT_LE(worst, 1e-3);  // measured 5.9e-4: half precision
}

}  // namespace
}  // namespace lg::test
