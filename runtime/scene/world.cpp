#include "runtime/scene/world.h"

#include <atomic>

namespace lg {
namespace {

// Process-wide, so two worlds never share a revision and a renderer switching worlds re-uploads.
uint64_t next_revision() {
  static std::atomic<uint64_t> counter{0};
  return ++counter;
}

template <class T>
T& element(std::vector<T>& items, int index, const char* what) {
  if (index < 0 || static_cast<size_t>(index) >= items.size())
    throw std::out_of_range(std::string("no ") + what + " " + std::to_string(index));
  return items[static_cast<size_t>(index)];
}

// The asset of `slot`, copied first when a SceneView still shares it. Assets are made as
// non-const T (make_shared<T> here and in add_mesh/add_texture) and only the World's pointers
// are to const, so writing through the const_cast is defined.
template <class T>
T& unshared(std::shared_ptr<const T>& slot) {
  if (slot.use_count() > 1) slot = std::make_shared<T>(*slot);
  return const_cast<T&>(*slot);
}

}  // namespace

Entity World::create() {
  uint32_t index;
  if (!free_.empty()) {
    index = free_.back();
    free_.pop_back();
  } else {
    index = static_cast<uint32_t>(generations_.size());
    generations_.push_back(0);
    live_.push_back(false);
  }
  live_[index] = true;
  ++live_count_;
  return {index, generations_[index]};
}

Entity World::create(std::string entity_name) {
  Entity e = create();
  add<Name>(e, {std::move(entity_name)});
  return e;
}

void World::destroy(Entity e) {
  check(e);
  std::apply([&](auto&... sets) { (sets.erase(e.index), ...); }, sets_);
  live_[e.index] = false;
  ++generations_[e.index];
  free_.push_back(e.index);
  --live_count_;
}

void World::check(Entity e) const {
  if (!alive(e)) throw std::invalid_argument("stale or null entity handle");
}

glm::mat4 World::world_matrix(Entity e) const {
  glm::mat4 m(1.0f);
  for (int depth = 0; alive(e); ++depth) {
    if (depth > 256) throw std::invalid_argument("the parent chain of an entity loops or is deeper than 256");
    const Transform* t = try_get<Transform>(e);
    if (!t) break;
    m = t->local_matrix() * m;
    e = t->parent;
  }
  return m;
}

void World::touch_assets() {
  asset_revision_ = next_revision();
}

int World::add_mesh(MeshData mesh) {
  touch_assets();
  meshes_.push_back(std::make_shared<MeshData>(std::move(mesh)));
  return static_cast<int>(meshes_.size() - 1);
}

int World::add_material(PbrMaterial material) {
  touch_assets();
  materials_.push_back(std::move(material));
  return static_cast<int>(materials_.size() - 1);
}

int World::add_texture(TextureData texture) {
  touch_assets();
  textures_.push_back(std::make_shared<TextureData>(std::move(texture)));
  return static_cast<int>(textures_.size() - 1);
}

MeshData& World::edit_mesh(int index) {
  touch_assets();
  return unshared(element(meshes_, index, "mesh"));
}

PbrMaterial& World::edit_material(int index) {
  touch_assets();
  return element(materials_, index, "material");
}

TextureData& World::edit_texture(int index) {
  touch_assets();
  return unshared(element(textures_, index, "texture"));
}

}  // namespace lg
