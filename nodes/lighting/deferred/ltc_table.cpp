#include "nodes/lighting/deferred/ltc_table.h"

#include <algorithm>
#include <cmath>

#include "nodes/lighting/deferred/area_light_math.h"

namespace lg {

const float kLtcTable[4 * kLtcSize * kLtcSize] = {
#include "nodes/lighting/deferred/ltc_table.inc"
};

double ltc_grid_n_dot_v(int i) {
  const double t = double(i) / (kLtcSize - 1);
  return std::max(1.0 - t * t, 1e-4);
}

double ltc_grid_roughness(int j) {
  return double(j) / (kLtcSize - 1);
}

double ltc_alpha(double roughness) {
  return std::max(roughness * roughness, 1e-3);
}

glm::vec4 ltc_lookup(float n_dot_v, float roughness) {
  constexpr int last = kLtcSize - 1;
  // clamp01 maps NaN to 0 (std::clamp passes it through, and int(NaN) is undefined).
  const float x = std::sqrt(1.0f - clamp01(n_dot_v)) * last;
  const float y = clamp01(roughness) * last;
  const int x0 = std::min(int(x), last - 1), y0 = std::min(int(y), last - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  auto at = [](int i, int j) {
    const float* e = &kLtcTable[4 * (j * kLtcSize + i)];
    return glm::vec4(e[0], e[1], e[2], e[3]);
  };
  const glm::vec4 low = at(x0, y0) + fx * (at(x0 + 1, y0) - at(x0, y0));
  const glm::vec4 high = at(x0, y0 + 1) + fx * (at(x0 + 1, y0 + 1) - at(x0, y0 + 1));
  return low + fy * (high - low);
}

glm::mat3 ltc_inverse(glm::vec4 e) {
  // glm is column-major: columns (m00, 0, m20), (0, 1, 0), (m02, 0, m22).
  return glm::mat3(glm::vec3(e.x, 0.0f, e.z), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(e.y, 0.0f, e.w));
}

std::array<glm::vec4, kLtcSize * kLtcSize> ltc_table_texels() {
  std::array<glm::vec4, kLtcSize * kLtcSize> texels;
  for (size_t k = 0; k < texels.size(); ++k)
    texels[k] = glm::vec4(kLtcTable[4 * k], kLtcTable[4 * k + 1], kLtcTable[4 * k + 2], kLtcTable[4 * k + 3]);
  return texels;
}

}  // namespace lg
