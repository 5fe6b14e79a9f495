// What the env tests share: random environments from fixed seeds, the HDR probes of
// ../shared/data/env as cube maps, and moving cube maps to and from the GPU.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "nodes/env/common/cube_map.h"
#include "runtime/gpu/image.h"

namespace lg {
class Context;
class Submitter;
}  // namespace lg

namespace lg::test {

// A smooth random sky (low-order lobes), a few bright spots and per-texel noise, all positive.
CubeImage random_environment(uint32_t size, uint64_t seed);

// ../shared/data/env/NAME resampled to a cube (4x4 supersampling), or nothing when missing.
std::optional<CubeImage> load_probe(const std::string& name, uint32_t face_size);

// An rgba16f cube map with its own memory.
Image make_cube(Context& context, const std::string& name, uint32_t size, uint32_t mips);
// Uploads `mips` (mip 0 first) and leaves the image in `layout`.
void upload_cube(Submitter& submitter, const Image& image, const std::vector<CubeImage>& mips, VkImageLayout layout);
// Reads one mip of a cube map in `layout`.
CubeImage read_cube(Submitter& submitter, const Image& image, uint32_t mip, VkImageLayout layout);

// The texels rounded to half precision, as an rgba16f image holds them (references must see
// what the GPU sees).
CubeImage round_to_half(CubeImage cube);
// Cube `cube` rotated by `rotation`, a quarter turn that maps texel centres onto texel centres:
// out(d) = cube(rotation^T d).
CubeImage rotate_quarter_turn(const CubeImage& cube, const glm::dmat3& rotation);

}  // namespace lg::test
