// libFuzzer harness: an environment file (HDR, EXR or PNG: ImageReader follows the first bytes)
// read as env.load and the CPU tracers read it: ImageReader, every texel, sanitize_equirect(),
// then the path tracer's importance-sampled EnvironmentMap, whose samples must be finite.
// Images over kMaxFuzzPixels stop after the header: the reader accepts up to 8192 x 8192, and
// reading such a one (1 GiB of floats) is the loader's stated cost, not something to fuzz.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "nodes/env/common/equirect.h"
#include "nodes/gi/path_tracer/environment_map.h"
#include "runtime/image/image_file.h"

namespace {

constexpr uint64_t kMaxFuzzPixels = uint64_t(1) << 20;

bool finite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_sampling(const lg::EnvironmentMap& map) {
  for (double u : {0.0, 0.25, 0.5, 0.999999}) {
    const std::optional<lg::EnvironmentMap::Sample> s = map.sample({u, 1.0 - u});
    if (!s) continue;
    if (!finite(s->direction) || !finite(s->radiance) || !std::isfinite(s->pdf) || s->pdf < 0.0 ||
        !std::isfinite(map.pdf(s->direction))) {
      std::fprintf(stderr, "environment sample at u=%g is not finite (pdf %g)\n", u, s->pdf);
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input = lg::fuzz::as_text(data, size);
  const lg::fuzz::InputFile file(input.starts_with("\x76\x2f\x31\x01") ? "env.exr" : "env.hdr", input);
  try {
    lg::ImageReader reader(file.path());
    const uint64_t pixels = uint64_t(reader.width()) * reader.height();
    if (pixels > kMaxFuzzPixels) return 0;
    lg::Equirect image{reader.width(), reader.height(), std::vector<float>(pixels * 4)};
    reader.read_rgba(image.rgba);
    lg::sanitize_equirect(image.rgba, 1.0);
    check_sampling(lg::EnvironmentMap::from_image(std::move(image)));
  } catch (const lg::ImageFileError&) {
  }
  return 0;
}
