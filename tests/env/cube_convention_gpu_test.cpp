// The cube-map convention against the device: a cube whose texels hold their own (face, i, j),
// sampled by samplerCube along the CPU's cube_direction of each texel centre, must give that
// texel; and the GLSL cube_direction and cube_face_uv must agree with the CPU's.
#include <gtest/gtest.h>

#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "nodes/env/common/cube_map.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/transfer.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg {
std::span<const EmbeddedShader> env_test_shaders();  // generated
}

namespace lg::test {
namespace {

struct Query {
  float direction[4], face_uv[4];
};
struct Answer {
  float sampled[4], direction[4], face_uv[4];
};

class CubeConventionGpuTest : public GpuTest {};

TEST_F(CubeConventionGpuTest, SamplerCubeAndShadersAgreeWithTheCpu) {
  const uint32_t size = 8;
  CubeImage ids(size);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i) ids.at(f, i, j) = glm::dvec4(f, i, j, 1);  // exact in half
  Image cube = make_cube(context(), "ids", size, 1);
  upload_cube(submitter(), cube, {ids}, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);

  std::vector<Query> queries;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i) {
        const double u = (i + unit(rng)) / size, v = (j + unit(rng)) / size;  // inside the texel
        const glm::dvec3 d = cube_direction(f, u, v);
        queries.push_back({{float(d.x), float(d.y), float(d.z), 0}, {float(f), float(u), float(v), 0}});
      }
  Buffer in = Buffer::dedicated(context(), {.name = "queries", .size = queries.size() * sizeof(Query)});
  Buffer out = Buffer::dedicated(context(), {.name = "answers", .size = queries.size() * sizeof(Answer)});
  upload_buffer(submitter(), in, std::as_bytes(std::span(queries)));
  Sampler nearest(context(), {.filter = Filter::nearest});
  const Pipeline& p = pipelines().compute({"sample_cube",
                                           find_shader(env_test_shaders(), "tests/env/shaders/sample_cube.comp"),
                                           {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}});
  submitter().run([&](VkCommandBuffer cmd) {
    const DescriptorWrite writes[] = {sampled_image(0, cube.view(), nearest.handle()), storage_buffer(1, in.handle()),
                                      storage_buffer(2, out.handle())};
    bind_pipeline(context(), cmd, p, writes);
    vkCmdDispatch(cmd, uint32_t((queries.size() + 63) / 64), 1, 1);
    memory_barrier(cmd);
  });
  std::vector<Answer> answers(queries.size());
  const std::vector<std::byte> bytes = read_buffer(submitter(), out);
  std::memcpy(answers.data(), bytes.data(), answers.size() * sizeof(Answer));
  size_t q = 0;
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i, ++q) {
        const Answer& a = answers[q];
        EXPECT_EQ(a.sampled[0], float(f));
        EXPECT_EQ(a.sampled[1], float(i)) << "face " << f;
        EXPECT_EQ(a.sampled[2], float(j)) << "face " << f;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.direction[c], queries[q].direction[c], 1e-6);
        EXPECT_EQ(a.face_uv[0], float(f));
        EXPECT_NEAR(a.face_uv[1], queries[q].face_uv[1], 1e-6);
        EXPECT_NEAR(a.face_uv[2], queries[q].face_uv[2], 1e-6);
      }
}

}  // namespace
}  // namespace lg::test
