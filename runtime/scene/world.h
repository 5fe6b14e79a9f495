// The ECS world: entities (world.create()), components in one sparse set per type
// (component_set.h), and the assets entities refer to by index (meshes, materials, textures).
// Handles are checked: using a destroyed entity throws std::invalid_argument, try_get() and
// alive() answer false instead. make_scene_view() (scene_view_builder.h) flattens a world for
// the frame's passes.
#pragma once

#include <algorithm>
#include <glm/mat4x4.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "runtime/scene/component_set.h"
#include "runtime/scene/components.h"
#include "runtime/scene/entity.h"
#include "runtime/scene/scene_view.h"

namespace lg {

class World {
 public:
  std::string name = "world";
  // The camera the view is seen through; when it is not alive with a Camera, make_scene_view()
  // takes the Camera entity with the lowest index.
  Entity active_camera;
  // What importers left out of the files they read (an optional extension they do not support),
  // one line each naming the file; the world loads without it.
  std::vector<std::string> warnings;

  Entity create();
  Entity create(std::string name);  // with a Name component
  bool alive(Entity e) const {
    return e.index < generations_.size() && generations_[e.index] == e.generation && live_[e.index];
  }
  // Removes every component of `e`; its index is reused by a later create() with a new generation.
  void destroy(Entity e);
  size_t entity_count() const { return live_count_; }

  template <class T>
  T& add(Entity e, T value = {}) {
    check(e);
    return set<T>().put(e.index, std::move(value));
  }
  template <class T>
  bool has(Entity e) const {
    return alive(e) && set<T>().contains(e.index);
  }
  template <class T>
  T* try_get(Entity e) {
    return alive(e) ? set<T>().find(e.index) : nullptr;
  }
  template <class T>
  const T* try_get(Entity e) const {
    return alive(e) ? set<T>().find(e.index) : nullptr;
  }
  template <class T>
  T& get(Entity e) {
    return *checked(e, try_get<T>(e));
  }
  template <class T>
  const T& get(Entity e) const {
    return *checked(e, try_get<T>(e));
  }
  template <class T>
  bool remove(Entity e) {
    check(e);
    return set<T>().erase(e.index);
  }
  template <class T>
  size_t count() const {
    return set<T>().size();
  }

  // Calls f(Entity, First&, Rest&...) for every entity that has all the listed components, in
  // the dense order of First's set. f must not add or remove components of those types.
  template <class First, class... Rest, class F>
  void each(F&& f) {
    each_in<First, Rest...>(*this, f);
  }
  template <class First, class... Rest, class F>
  void each(F&& f) const {
    each_in<First, Rest...>(*this, f);
  }

  // The entity's frame in world space: its Transform composed with its parents'. Identity
  // without a Transform; a parent chain that loops or is deeper than 256 throws.
  glm::mat4 world_matrix(Entity e) const;

  // Assets. Every change moves asset_revision() to a number never used before in this process,
  // so a renderer re-uploads when it differs from the one it uploaded. Meshes and textures are
  // held through shared pointers that SceneViews share (scene_view.h); none is ever null. An
  // edit_ function copies an asset that a view still holds before handing it out, so views keep
  // what they saw; its reference is for one edit: call it again after the next make_scene_view()
  // or asset change, or the change may reach a view without a new revision.
  int add_mesh(MeshData mesh);
  int add_material(PbrMaterial material);
  int add_texture(TextureData texture);
  const std::vector<std::shared_ptr<const MeshData>>& meshes() const { return meshes_; }
  const std::vector<PbrMaterial>& materials() const { return materials_; }
  const std::vector<std::shared_ptr<const TextureData>>& textures() const { return textures_; }
  MeshData& edit_mesh(int index);
  PbrMaterial& edit_material(int index);
  TextureData& edit_texture(int index);
  uint64_t asset_revision() const { return asset_revision_; }

 private:
  using Sets = std::tuple<ComponentSet<Name>, ComponentSet<Transform>, ComponentSet<Camera>, ComponentSet<MeshRenderer>,
                          ComponentSet<DirectionalLight>, ComponentSet<PointLight>, ComponentSet<SpotLight>,
                          ComponentSet<SphereLight>, ComponentSet<TubeLight>, ComponentSet<RectLight>,
                          ComponentSet<EnvironmentLight>, ComponentSet<IrradianceVolume>, ComponentSet<ReflectionProbe>,
                          ComponentSet<PostProcessSettings>>;

  template <class T>
  ComponentSet<T>& set() {
    return std::get<ComponentSet<T>>(sets_);
  }
  template <class T>
  const ComponentSet<T>& set() const {
    return std::get<ComponentSet<T>>(sets_);
  }
  void check(Entity e) const;
  template <class T>
  T* checked(Entity e, T* value) const {
    if (!value)
      throw std::invalid_argument(alive(e) ? "the entity lacks the component" : "stale or null entity handle");
    return value;
  }
  template <class First, class... Rest, class Self, class F>
  static void each_in(Self& self, F& f) {
    // Copy the owners: f may destroy or add entities that hold none of the iterated components.
    std::vector<uint32_t> owners = self.template set<First>().owners();
    for (uint32_t index : owners) {
      Entity e{index, self.generations_[index]};
      auto* first = self.template set<First>().find(index);
      if (!first || !(self.template set<Rest>().contains(index) && ...)) continue;
      f(e, *first, *self.template set<Rest>().find(index)...);
    }
  }
  void touch_assets();

  Sets sets_;
  std::vector<uint32_t> generations_;
  std::vector<bool> live_;
  std::vector<uint32_t> free_;
  size_t live_count_ = 0;
  std::vector<std::shared_ptr<const MeshData>> meshes_;
  std::vector<PbrMaterial> materials_;
  std::vector<std::shared_ptr<const TextureData>> textures_;
  uint64_t asset_revision_ = 0;
};

}  // namespace lg
