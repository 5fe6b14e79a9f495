// AlphaCoverage: see alpha_coverage.h.
#include "nodes/raytrace/alpha_coverage.h"

#include "nodes/raytrace/surface_material.h"
#include "runtime/scene/light_alpha.h"

namespace lg {

AlphaCoverage::AlphaCoverage(const WorldMesh& mesh, const SceneView& view) {
  for (size_t d = 0; d < mesh.parts.size() && d < view.draws.size(); ++d) {
    const PbrMaterial& m = view.material_of(view.draws[d]);
    const double threshold = light_alpha_cutoff(m);
    if (!(threshold > 0.0)) continue;  // alpha is never below a cutoff of 0
    const int t = m.base_color_texture.texture;
    materials_.push_back(
        {m, t >= 0 && size_t(t) < view.textures.size() ? view.textures[size_t(t)] : nullptr, threshold});
    const WorldMesh::Part& part = mesh.parts[d];
    for (uint32_t i = part.first_triangle; i < part.first_triangle + part.triangle_count; ++i) {
      Corners c;
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.indices[3 * size_t(i) + k];
        c.uv0[k] = mesh.uvs[v], c.uv1[k] = mesh.uvs1[v], c.color[k] = mesh.colors[v];
      }
      c.material = uint32_t(materials_.size() - 1);
      triangles_.push_back(i);
      corners_.push_back(c);
    }
  }
}

bool AlphaCoverage::transparent(uint32_t index, glm::vec2 barycentric) const {
  const Corners& c = corners_[index];
  const Material& m = materials_[c.material];
  const double wb = barycentric.x, wc = barycentric.y, wa = 1.0 - wb - wc;
  auto interpolate = [&]<class T>(const T(&values)[3]) {
    using D = glm::vec<T::length(), double>;
    return wa * D(values[0]) + wb * D(values[1]) + wc * D(values[2]);
  };
  const SurfaceTexcoords at{interpolate(c.uv0), interpolate(c.uv1), interpolate(c.color)};
  return coverage_alpha(m.material, m.base_color.get(), at) < m.threshold;
}

}  // namespace lg
