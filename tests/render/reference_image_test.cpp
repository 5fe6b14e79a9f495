// The first frame of examples/minimal.json on the embedded default world at 320x180 against a
// committed reference image (tests/render/reference/), produced by this code and checked by eye
// once. Run with LUMAGRAPH_UPDATE_REFERENCES=1 to write a new reference after a deliberate
// change, then look at it before committing it.
//
// Tolerance: lavapipe compiles shaders with LLVM for the CPU it runs on, so another CPU (other
// vector units, fused multiply-adds) may round differently: at most 3/255 on any channel of
// 99.9% of pixels, and a mean difference under 0.25/255. A change in lighting, shadows or tone
// curve moves far more pixels than that.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "api/renderer.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{320, 180};
constexpr const char* kReference = "tests/render/reference/minimal-default-320x180.png";

TEST(ReferenceImage, MinimalGraphOnTheDefaultWorld) {
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.load_graph("examples/minimal.json");
  World world = default_world();
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << describe(messages);
  std::vector<float> pixels = renderer.read_output();

  if (std::getenv("LUMAGRAPH_UPDATE_REFERENCES")) {
    save_image(kReference, kFrame.width, kFrame.height, pixels);
    GTEST_SKIP() << "wrote " << kReference << "; look at it before committing";
  }
  ImageData reference = load_image(kReference);
  ASSERT_EQ(reference.width, kFrame.width);
  ASSERT_EQ(reference.height, kFrame.height);
  size_t over = 0;
  double sum = 0, worst = 0;
  for (size_t p = 0; p < pixels.size() / 4; ++p) {
    double pixel_worst = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(std::round(pixels[p * 4 + c] * 255.0) - std::round(reference.rgba[p * 4 + c] * 255.0));
      sum += d;
      pixel_worst = std::max(pixel_worst, d);
    }
    worst = std::max(worst, pixel_worst);
    if (pixel_worst > 3) ++over;
  }
  const double pixels_count = double(pixels.size() / 4);
  const double mean = sum / (3 * pixels_count);
  std::cout << "against " << kReference << ": mean " << mean << "/255, worst " << worst << "/255, " << over
            << " pixels over 3/255\n";
  EXPECT_LE(double(over), 0.001 * pixels_count);
  EXPECT_LT(mean, 0.25);
}

}  // namespace
}  // namespace lg::test
