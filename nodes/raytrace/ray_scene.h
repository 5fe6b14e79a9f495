// An Embree scene of world-space triangles for CPU ray queries: closest hit and any hit
// (occlusion), thread-safe once built. Built from a SceneView (every draw's mesh moved into world
// space by its transform, draws in order) or from raw world-space triangles. Zero-area triangles
// are kept (they are never hit); a non-finite position is an error that names the mesh and vertex.
// Built from a SceneView, every query passes through alpha-tested surfaces where their alpha is
// below the cutoff (alpha_coverage.h), and the scene knows which triangles are single-sided (for
// camera rays: first_camera_hit()); raw triangles are opaque and single-sided, as PbrMaterial's
// defaults. Every query hits both sides of every triangle.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

struct WorldMesh;

struct RayHit {
  float distance = 0.0f;        // along the (unit) ray direction
  glm::vec3 normal{0.0f};       // unit geometric normal, the side counter-clockwise triangles face
  uint32_t primitive = 0;       // index into the scene's triangles (draws in order, then each mesh's)
  glm::vec2 barycentric{0.0f};  // weights of the triangle's second and third corners at the hit
};

class RayScene {
 public:
  // The draws as make_world_mesh() flattens them. Throws std::invalid_argument for a non-finite
  // position or a bad mesh (mesh_problem()), naming the mesh.
  explicit RayScene(const SceneView& view);
  // `mesh` is make_world_mesh(view), for callers that keep it.
  RayScene(const WorldMesh& mesh, const SceneView& view);
  // `indices` holds three per triangle into `positions`; `name` appears in error messages.
  RayScene(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
           const std::string& name = "triangles");
  ~RayScene();
  RayScene(RayScene&&) noexcept;
  RayScene& operator=(RayScene&&) noexcept;

  // The closest hit with distance in (0, t_max], if any. `direction` must be unit length.
  std::optional<RayHit> intersect(glm::vec3 origin, glm::vec3 direction, float t_max) const;
  // Whether anything lies along the ray within (0, t_max].
  bool occluded(glm::vec3 origin, glm::vec3 direction, float t_max) const;
  // occluded() for up to packet_size rays from one origin at once, through Embree's packet
  // traversal (faster for such coherent rays); sets occluded[i] for each direction.
  static constexpr size_t packet_size = 8;
  void occluded_packet(glm::vec3 origin, std::span<const glm::vec3> directions, float t_max,
                       std::span<bool> occluded) const;
  // intersect() for up to packet_size rays from one origin at once.
  void intersect_packet(glm::vec3 origin, std::span<const glm::vec3> directions, float t_max,
                        std::span<std::optional<RayHit>> hits) const;

  size_t triangle_count() const { return indices_.size() / 3; }
  // World-space corners of triangle `primitive`.
  std::array<glm::vec3, 3> triangle(uint32_t primitive) const;
  // The box around every position (empty() when there are none).
  glm::vec3 bounds_min() const { return bounds_min_; }
  glm::vec3 bounds_max() const { return bounds_max_; }
  bool empty() const { return indices_.empty(); }
  // Whether triangle `primitive`'s material is single-sided (the G-buffer may cull its back).
  bool single_sided(uint32_t primitive) const { return double_sided_.empty() || !double_sided_[primitive]; }

 private:
  void build(const SceneView* view, const WorldMesh* mesh);
  uint32_t primitive(unsigned geometry, unsigned local) const { return geometry_triangles_[geometry][local]; }
  RayHit make_hit(float distance, uint32_t primitive, glm::vec2 barycentric, glm::vec3 direction) const;

  std::vector<glm::vec3> positions_;
  std::vector<uint32_t> indices_;
  std::vector<uint8_t> double_sided_;                      // one per triangle; empty: none is
  std::vector<std::vector<uint32_t>> geometry_triangles_;  // per Embree geometry, its triangles' indices here
  glm::vec3 bounds_min_{1e30f}, bounds_max_{-1e30f};
  struct Embree;
  std::unique_ptr<Embree> embree_;
};

}  // namespace lg
