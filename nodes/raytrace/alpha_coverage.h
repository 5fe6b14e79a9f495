// Where rays pass through alpha-tested surfaces: the triangles of a flattened scene
// (world_mesh.h) whose material is alphaMode MASK, and whether a point on one has alpha below
// its cutoff, as the G-buffer's alpha test decides (coverage_alpha(): base colour factor x
// texture x vertex colour alpha, the texture at level 0 through its set and transform). BLEND
// materials are tested as MASK with cutoff 0.5 (light_alpha_cutoff()). Holds copies of
// what it reads (corner uvs and alphas, materials, shared textures), so it outlives the view.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "nodes/raytrace/world_mesh.h"
#include "runtime/scene/scene_view.h"

namespace lg {

class AlphaCoverage {
 public:
  AlphaCoverage(const WorldMesh& mesh, const SceneView& view);

  // The triangles that are alpha-tested, in the mesh's order; the others are opaque.
  const std::vector<uint32_t>& tested_triangles() const { return triangles_; }
  // Whether a ray passes through tested triangle `index` (into tested_triangles()) at the point
  // whose barycentric weights of the second and third corners are `barycentric`.
  bool transparent(uint32_t index, glm::vec2 barycentric) const;

 private:
  struct Material {
    PbrMaterial material;
    std::shared_ptr<const TextureData> base_color;  // null where the material has no texture
    double threshold = 0.0;
  };
  struct Corners {
    glm::vec2 uv0[3], uv1[3];
    glm::vec4 color[3];
    uint32_t material = 0;  // into materials_
  };
  std::vector<uint32_t> triangles_;
  std::vector<Corners> corners_;  // one per tested triangle
  std::vector<Material> materials_;
};

}  // namespace lg
