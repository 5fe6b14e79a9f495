#include "tests/env/env_test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <random>

#include "nodes/env/common/equirect.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/submit.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"
#include "runtime/image/image_file.h"

namespace lg::test {

CubeImage random_environment(uint32_t size, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  auto random_direction = [&] { return glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng))); };
  struct Lobe {
    glm::dvec3 axis, color;
    double sharpness;
  };
  std::vector<Lobe> lobes;
  for (int k = 0; k < 6; ++k)
    lobes.push_back({random_direction(), glm::dvec3(unit(rng), unit(rng), unit(rng)) * 2.0, 1 + 20 * unit(rng)});
  for (int k = 0; k < 3; ++k)  // bright spots a few texels wide
    lobes.push_back({random_direction(), glm::dvec3(unit(rng), unit(rng), unit(rng)) * 40.0, 2000 + 4000 * unit(rng)});
  CubeImage cube(size);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i) {
        const glm::dvec3 d = cube.direction(f, i, j);
        glm::dvec3 c(0.2 + 0.1 * unit(rng), 0.2 + 0.1 * unit(rng), 0.2 + 0.1 * unit(rng));
        for (const Lobe& l : lobes) c += l.color * std::exp(l.sharpness * (glm::dot(d, l.axis) - 1));
        cube.at(f, i, j) = glm::dvec4(c, 1.0);
      }
  return cube;
}

std::optional<CubeImage> load_probe(const std::string& name, uint32_t face_size) {
  const std::string path = "../shared/data/env/" + name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  ImageData data = load_image(path);
  return equirect_to_cube(Equirect{data.width, data.height, std::move(data.rgba)}, face_size, 4);
}

Image make_cube(Context& context, const std::string& name, uint32_t size, uint32_t mips) {
  return Image::dedicated(context, {.name = name,
                                    .kind = ImageKind::cube,
                                    .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                    .width = size,
                                    .height = size,
                                    .mips = mips,
                                    .layers = 6});
}

void upload_cube(Submitter& submitter, const Image& image, const std::vector<CubeImage>& mips, VkImageLayout layout) {
  VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  for (uint32_t m = 0; m < mips.size(); ++m)
    for (int f = 0; f < 6; ++f) {
      upload_image(submitter, image, mips[m].face_floats(f), layout, {m, uint32_t(f)}, old_layout);
      old_layout = layout;
    }
}

CubeImage read_cube(Submitter& submitter, const Image& image, uint32_t mip, VkImageLayout layout) {
  CubeImage cube(std::max(1u, image.desc().width >> mip));
  for (int f = 0; f < 6; ++f) {
    const std::vector<float> texels = read_image(submitter, image, layout, {mip, uint32_t(f)});
    for (uint32_t t = 0; t < cube.size * cube.size; ++t)
      cube.texels[f * cube.size * cube.size + t] =
          glm::dvec4(texels[4 * t], texels[4 * t + 1], texels[4 * t + 2], texels[4 * t + 3]);
  }
  return cube;
}

CubeImage round_to_half(CubeImage cube) {
  for (glm::dvec4& t : cube.texels)
    for (int c = 0; c < 4; ++c) t[c] = half_to_float(float_to_half(float(t[c])));
  return cube;
}

CubeImage rotate_quarter_turn(const CubeImage& cube, const glm::dmat3& rotation) {
  CubeImage out(cube.size);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < cube.size; ++j)
      for (uint32_t i = 0; i < cube.size; ++i) {
        const CubeCoord c = cube_coord(glm::transpose(rotation) * cube.direction(f, i, j));
        const auto texel = [&](double x) { return std::min(cube.size - 1, uint32_t(x * cube.size)); };
        out.at(f, i, j) = cube.at(c.face, texel(c.u), texel(c.v));
      }
  return out;
}

}  // namespace lg::test
