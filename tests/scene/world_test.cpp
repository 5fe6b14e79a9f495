// The sparse-set store: handles, generations, components, iteration, parents and asset
// revisions, and random add/remove/destroy sequences checked against a std::map model.
#include "runtime/scene/world.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

namespace lg {
namespace {

TEST(World, AddGetRemoveDestroy) {
  World w;
  Entity a = w.create("a"), b = w.create();
  EXPECT_TRUE(w.alive(a));
  EXPECT_EQ(w.entity_count(), 2u);
  EXPECT_EQ(w.get<Name>(a).value, "a");
  w.add<PointLight>(b, {{1, 0, 0}, 2.0f, 0.0f});
  EXPECT_TRUE(w.has<PointLight>(b));
  EXPECT_FALSE(w.has<PointLight>(a));
  EXPECT_EQ(w.try_get<PointLight>(a), nullptr);
  EXPECT_FLOAT_EQ(w.get<PointLight>(b).intensity, 2.0f);
  w.add<PointLight>(b, {{1, 0, 0}, 3.0f, 0.0f});  // replaces
  EXPECT_EQ(w.count<PointLight>(), 1u);
  EXPECT_FLOAT_EQ(w.get<PointLight>(b).intensity, 3.0f);
  EXPECT_THROW(w.get<PointLight>(a), std::invalid_argument);
  EXPECT_TRUE(w.remove<PointLight>(b));
  EXPECT_FALSE(w.remove<PointLight>(b));
  w.destroy(a);
  EXPECT_FALSE(w.alive(a));
  EXPECT_EQ(w.entity_count(), 1u);
}

TEST(World, StaleHandlesAreDetectedAfterTheSlotIsReused) {
  World w;
  Entity a = w.create();
  w.add<Camera>(a);
  w.destroy(a);
  Entity b = w.create();
  EXPECT_EQ(b.index, a.index);
  EXPECT_NE(b.generation, a.generation);
  EXPECT_FALSE(w.alive(a));
  EXPECT_FALSE(w.has<Camera>(b));  // destroy() removed every component
  EXPECT_EQ(w.try_get<Camera>(a), nullptr);
  EXPECT_THROW(w.add<Camera>(a), std::invalid_argument);
  EXPECT_THROW(w.destroy(a), std::invalid_argument);
  EXPECT_THROW(w.get<Camera>(Entity{}), std::invalid_argument);
}

TEST(World, EachVisitsExactlyTheEntitiesWithEveryListedComponent) {
  World w;
  std::set<uint64_t> expected;
  for (int i = 0; i < 20; ++i) {
    Entity e = w.create();
    if (i % 2 == 0) w.add<Transform>(e);
    if (i % 3 == 0) w.add<MeshRenderer>(e, {i, -1});
    if (i % 6 == 0) expected.insert(e.id());
  }
  std::set<uint64_t> seen;
  w.each<MeshRenderer, Transform>([&](Entity e, MeshRenderer& r, Transform&) {
    seen.insert(e.id());
    EXPECT_EQ(r.mesh, static_cast<int>(e.index));
  });
  EXPECT_EQ(seen, expected);
  const World& c = w;
  size_t count = 0;
  c.each<Transform>([&](Entity, const Transform&) { ++count; });
  EXPECT_EQ(count, 10u);
}

TEST(World, WorldMatrixComposesParents) {
  World w;
  Entity parent = w.create(), child = w.create();
  w.add<Transform>(parent, {{1, 0, 0}, glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0)), glm::vec3(2.0f), {}});
  w.add<Transform>(child, {{0, 0, -1}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), parent});
  glm::vec3 origin = glm::vec3(w.world_matrix(child) * glm::vec4(0, 0, 0, 1));
  // (0,0,-1) scaled by 2 is (0,0,-2); turned 90 degrees about Y it is (-2,0,0); moved by (1,0,0).
  EXPECT_NEAR(origin.x, -1.0f, 1e-5f);
  EXPECT_NEAR(origin.y, 0.0f, 1e-5f);
  EXPECT_NEAR(origin.z, 0.0f, 1e-5f);
  w.get<Transform>(parent).parent = child;  // a loop
  EXPECT_THROW(w.world_matrix(child), std::invalid_argument);
}

TEST(World, AssetChangesMoveTheRevisionToAnUnusedNumber) {
  World a, b;
  std::set<uint64_t> seen{a.asset_revision()};
  auto fresh = [&](uint64_t r) { return seen.insert(r).second; };
  a.add_mesh({});
  EXPECT_TRUE(fresh(a.asset_revision()));
  b.add_material({});
  EXPECT_TRUE(fresh(b.asset_revision()));
  a.edit_mesh(0).name = "x";
  EXPECT_TRUE(fresh(a.asset_revision()));
  a.add_texture({});
  EXPECT_TRUE(fresh(a.asset_revision()));
  EXPECT_THROW(a.edit_material(3), std::out_of_range);
}

// Random create/destroy/add/remove against a model: a map from live entity to its components.
TEST(World, RandomSequencesAgreeWithAMapModel) {
  std::mt19937 rng(1234);
  World w;
  std::map<uint64_t, std::pair<Entity, std::map<int, int>>> model;  // id -> (entity, kind -> value)
  std::vector<Entity> dead;
  auto pick = [&](auto& container) {
    return std::next(container.begin(), static_cast<long>(rng() % container.size()));
  };
  for (int step = 0; step < 20000; ++step) {
    int action = static_cast<int>(rng() % 10);
    if (action == 0 || model.empty()) {
      Entity e = w.create();
      ASSERT_EQ(model.count(e.id()), 0u);
      model[e.id()] = {e, {}};
    } else if (action == 1) {
      auto it = pick(model);
      w.destroy(it->second.first);
      dead.push_back(it->second.first);
      model.erase(it);
    } else {
      auto it = pick(model);
      Entity e = it->second.first;
      auto& comps = it->second.second;
      int value = static_cast<int>(rng() % 1000);
      bool mesh = rng() % 2;
      int kind = mesh ? 0 : 1;
      if (action < 7) {
        if (mesh)
          w.add<MeshRenderer>(e, {value, value});
        else
          w.add<PointLight>(e, {glm::vec3(0.0f), float(value), 0.0f});
        comps[kind] = value;
      } else {
        bool removed = mesh ? w.remove<MeshRenderer>(e) : w.remove<PointLight>(e);
        EXPECT_EQ(removed, comps.erase(kind) == 1);
      }
    }
    if (step % 500 != 0) continue;
    // Full comparison every 500 steps.
    ASSERT_EQ(w.entity_count(), model.size());
    size_t meshes = 0, lights = 0;
    for (const auto& [id, entry] : model) {
      const auto& [e, comps] = entry;
      ASSERT_TRUE(w.alive(e));
      const MeshRenderer* r = w.try_get<MeshRenderer>(e);
      const PointLight* l = w.try_get<PointLight>(e);
      ASSERT_EQ(r != nullptr, comps.count(0) == 1);
      ASSERT_EQ(l != nullptr, comps.count(1) == 1);
      if (r) {
        EXPECT_EQ(r->mesh, comps.at(0));
      }
      if (l) {
        EXPECT_EQ(l->intensity, float(comps.at(1)));
      }
      meshes += r != nullptr;
      lights += l != nullptr;
    }
    EXPECT_EQ(w.count<MeshRenderer>(), meshes);
    EXPECT_EQ(w.count<PointLight>(), lights);
    size_t visited = 0;
    w.each<MeshRenderer>([&](Entity e, MeshRenderer& r) {
      ++visited;
      ASSERT_EQ(model.count(e.id()), 1u);
      EXPECT_EQ(r.mesh, model[e.id()].second.at(0));
    });
    EXPECT_EQ(visited, meshes);
    for (Entity e : dead) EXPECT_FALSE(w.alive(e));
  }
}

}  // namespace
}  // namespace lg
