// Phase 6, lower: resource extents, layers, mips and bytes for each size rule, as a user
// reading the schema would compute them by hand, at several frame sizes (what --size sets).
#include "graph/compiler/lower.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "graph/compiler/cull.h"
#include "graph/compiler/resolve.h"
#include "graph/compiler/specialize.h"
#include "graph/compiler/validate.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

using test::compile_ok;
using test::load_example;

// Bytes of an image with a mip chain, each level half the one above (rounded down, at least 1).
uint64_t image_bytes(uint32_t w, uint32_t h, uint32_t layers, uint32_t mips, uint32_t bytes_per_texel) {
  uint64_t texels = 0;
  for (uint32_t m = 0; m < mips; ++m) texels += uint64_t{std::max(1u, w >> m)} * std::max(1u, h >> m);
  return texels * layers * bytes_per_texel;
}

const LoweredResource& resource(const Plan& plan, std::string_view name) {
  int r = test::resource_at(plan, name);
  if (r < 0) throw std::runtime_error("no resource " + std::string(name));
  return plan.resources[r].desc;
}

CompileOptions at(uint32_t w, uint32_t h) {
  CompileOptions o;
  o.frame = {w, h};
  return o;
}

TEST(CompilerLower, GBufferIsTheFrameSizeTimesResolutionScale) {
  struct Case {
    uint32_t w, h;
    double scale;
    uint32_t expect_w, expect_h;
  };
  // floor(w * scale): 1000 x 0.75 = 750, 333 x 0.75 = 249.75 -> 249.
  for (Case c : {Case{1280, 720, 1.0, 1280, 720}, Case{1920, 1080, 0.5, 960, 540}, Case{1000, 333, 0.75, 750, 249},
                 Case{640, 480, 2.0, 1280, 960}, Case{3, 3, 0.25, 1, 1}}) {
    SCOPED_TRACE(std::to_string(c.w) + "x" + std::to_string(c.h) + " scale " + std::to_string(c.scale));
    Graph g = load_example("examples/minimal.json");
    test::node_named(g, "gbuf").params.set("resolution_scale", c.scale);
    Plan plan = compile_ok(g, builtin_registry(), at(c.w, c.h));
    struct Component {
      const char* name;
      const char* format;
      uint32_t bytes_per_texel;
    };
    for (Component k :
         {Component{"depth", "d32f", 4}, Component{"normal", "rgb10a2", 4}, Component{"albedo", "rgba8_srgb", 4},
          Component{"material", "rg8", 2}, Component{"motion", "rg16f", 4}}) {
      const LoweredResource& r = resource(plan, std::string("gbuf.gbuffer.") + k.name);
      EXPECT_EQ(r.width, c.expect_w) << k.name;
      EXPECT_EQ(r.height, c.expect_h) << k.name;
      EXPECT_EQ(r.format, k.format);
      EXPECT_EQ(r.layers, 1u);
      EXPECT_EQ(r.mips, 1u);
      EXPECT_EQ(r.bytes, uint64_t{c.expect_w} * c.expect_h * k.bytes_per_texel) << k.name;
      EXPECT_EQ(r.depth_format, std::string(k.name) == "depth");
    }
    // Outputs sized from the G-buffer input follow it, not the frame.
    const LoweredResource& color = resource(plan, "light.color");
    EXPECT_EQ(color.width, c.expect_w);
    EXPECT_EQ(color.height, c.expect_h);
    EXPECT_EQ(color.bytes, uint64_t{c.expect_w} * c.expect_h * 8);                            // rgba16f
    EXPECT_EQ(resource(plan, "tonemap.color").bytes, uint64_t{c.expect_w} * c.expect_h * 4);  // rgba8
  }
}

TEST(CompilerLower, BloomChainIsHalfSizeWithOneMipPerLevel) {
  struct Case {
    uint32_t w, h, levels, expect_mips;
  };
  // A 64x36 chain has 7 levels at most (64, 32, 16, 8, 4, 2, 1), so 12 is clamped to 7.
  for (Case c : {Case{1280, 720, 6, 6}, Case{1920, 1080, 1, 1}, Case{1001, 601, 4, 4}, Case{128, 72, 12, 7}}) {
    SCOPED_TRACE(std::to_string(c.w) + "x" + std::to_string(c.h) + " levels " + std::to_string(c.levels));
    Graph g = load_example("examples/post.json");
    test::node_named(g, "bloom").params.set("levels", static_cast<int>(c.levels));
    Plan plan = compile_ok(g, builtin_registry(), at(c.w, c.h));
    const LoweredResource& chain = resource(plan, "bloom/chain");
    EXPECT_EQ(chain.width, c.w / 2);
    EXPECT_EQ(chain.height, c.h / 2);
    EXPECT_EQ(chain.mips, c.expect_mips);
    EXPECT_EQ(chain.format, "rgba16f");
    EXPECT_EQ(chain.bytes, image_bytes(c.w / 2, c.h / 2, 1, c.expect_mips, 8));
    // Its output is full size, like its input.
    EXPECT_EQ(resource(plan, "bloom.color").width, c.w);
    EXPECT_EQ(resource(plan, "bloom.color").height, c.h);
  }
}

TEST(CompilerLower, CubeMapsHaveSixLayersAndTheirMipChains) {
  for (int face : {1, 64, 128, 300}) {
    SCOPED_TRACE(face);
    Graph g = load_example("examples/default.json");
    test::node_named(g, "sky").params.set("face_size", face);
    test::node_named(g, "specular").params.set("face_size", face);
    Plan plan = compile_ok(g, builtin_registry());
    uint32_t f = static_cast<uint32_t>(face);
    uint32_t full = static_cast<uint32_t>(std::floor(std::log2(face))) + 1;  // 300 -> 9: 300 150 75 37 18 9 4 2 1
    const LoweredResource& sky = resource(plan, "sky.cube");
    EXPECT_EQ(sky.kind, ResourceKind::cube);
    EXPECT_EQ(sky.width, f);
    EXPECT_EQ(sky.height, f);
    EXPECT_EQ(sky.layers, 6u);
    EXPECT_EQ(sky.mips, full) << "mips: full";
    EXPECT_EQ(sky.bytes, image_bytes(f, f, 6, full, 8));
    // specular: mips = param (6 in default.json), clamped to the full chain.
    const LoweredResource& spec = resource(plan, "specular.specular");
    EXPECT_EQ(spec.layers, 6u);
    EXPECT_EQ(spec.mips, std::min(full, 6u));
    EXPECT_EQ(spec.bytes, image_bytes(f, f, 6, std::min(full, 6u), 8));
  }
}

TEST(CompilerLower, ShBufferHoldsOrderPlusOneSquaredCoefficients) {
  for (int order = 1; order <= 4; ++order) {
    Graph g = load_example("examples/default.json");
    test::node_named(g, "sh").params.set("order", order);
    Plan plan = compile_ok(g, builtin_registry());
    const LoweredResource& sh = resource(plan, "sh.sh");
    uint32_t coefficients = static_cast<uint32_t>((order + 1) * (order + 1));
    EXPECT_EQ(sh.kind, ResourceKind::buffer);
    EXPECT_EQ(sh.width, coefficients) << "order " << order;
    EXPECT_EQ(sh.height, 1u);
    EXPECT_EQ(sh.bytes, uint64_t{coefficients} * 16) << "one vec4 (16 bytes) per coefficient";
  }
  // The default order (2) when the file does not say.
  Graph g = load_example("examples/default.json");
  test::node_named(g, "sh").params = JsonValue::object();
  EXPECT_EQ(resource(compile_ok(g, builtin_registry()), "sh.sh").width, 9u);
}

TEST(CompilerLower, FrameSizeChangesFrameSizedResourcesOnly) {
  Plan small = compile_ok(load_example("examples/default.json"), builtin_registry(), at(640, 360));
  Plan large = compile_ok(load_example("examples/default.json"), builtin_registry(), at(2560, 1440));
  ASSERT_EQ(small.resources.size(), large.resources.size());
  for (size_t r = 0; r < small.resources.size(); ++r) {
    const LoweredResource& a = small.resources[r].desc;
    const LoweredResource& b = large.resources[r].desc;
    ASSERT_EQ(a.name, b.name);
    // Screen-space resources scale by 4 along each axis; env maps, LUTs, SH and the shadow map do not.
    bool screen = a.name.starts_with("gbuf.") || a.name.starts_with("gtao") || a.name.starts_with("light.") ||
                  a.name.starts_with("ibl.") || a.name.starts_with("tonemap.");
    if (screen) {
      EXPECT_EQ(b.width, a.width * 4) << a.name;
      EXPECT_EQ(b.height, a.height * 4) << a.name;
    } else {
      EXPECT_EQ(b.width, a.width) << a.name;
      EXPECT_EQ(b.bytes, a.bytes) << a.name;
    }
  }
  EXPECT_EQ(resource(small, "gtao/depth_mips").mips, 5u);       // fixed in the schema
  EXPECT_EQ(resource(small, "light/shadow_map").width, 2048u);  // param shadow_map_size
  EXPECT_EQ(small.frame.width, 640u);
}

// occlusion.gtao's upsample guide (surface, ao_guide, bent_low) is used only below
// resolution_scale 1: "only_when_scaled" makes it a 1x1 placeholder at 1 (it took 8.8 MiB at
// 1280x720 unused) and sizes it by the scale below 1.
TEST(CompilerLower, AResourceOnlyUsedWhenScaledIsAPlaceholderAtScaleOne) {
  for (double scale : {1.0, 0.5}) {
    SCOPED_TRACE("resolution_scale " + std::to_string(scale));
    Graph g = load_example("examples/default.json");
    test::node_named(g, "gtao").params.set("resolution_scale", scale);
    Plan plan = compile_ok(g, builtin_registry(), at(1280, 720));
    const uint32_t w = scale < 1 ? 640 : 1, h = scale < 1 ? 360 : 1;
    for (const char* name : {"gtao/surface", "gtao/ao_guide", "gtao/bent_low"}) {
      EXPECT_EQ(resource(plan, name).width, w) << name;
      EXPECT_EQ(resource(plan, name).height, h) << name;
    }
    EXPECT_EQ(resource(plan, "gtao/noisy").width, uint32_t(1280 * scale));  // the horizon grid, either way
  }
}

TEST(CompilerLower, AnExtentBeyondTheLimitIsAnError) {
  Graph g = load_example("examples/minimal.json");
  test::node_named(g, "gbuf").params.set("resolution_scale", 2.0);
  std::string errors = test::compile_errors(g, builtin_registry(), at(10000, 720));
  EXPECT_NE(errors.find("'gbuf.gbuffer.depth' would be 20000x1440, beyond the limit of 16384 texels a side"),
            std::string::npos)
      << errors;
}

TEST(CompilerLower, NamesSayWhichNodePortAndComponentEachResourceIs) {
  Plan plan = compile_ok(load_example("examples/default.json"), builtin_registry());
  for (const auto& r : plan.resources) {
    const std::string& id = plan.nodes[r.desc.node].id;
    // "node.port", "node.port.component", "node/internal" or "node.port@previous".
    EXPECT_TRUE(r.desc.name.starts_with(id + ".") || r.desc.name.starts_with(id + "/")) << r.desc.name;
  }
  EXPECT_GE(test::resource_at(plan, "gtao/depth_mips"), 0);
  EXPECT_GE(test::resource_at(plan, "gbuf.gbuffer.motion"), 0);
}

TEST(CompilerLower, StaticNodesGetCacheKeysThatFollowTheirInputsAndParams) {
  auto keys = [](const Plan& plan) {
    std::map<std::string, uint64_t> out;
    for (const auto& p : plan.passes)
      if (p.is_static) out[p.name] = p.cache_key;
    return out;
  };
  Plan base = compile_ok(load_example("examples/default.json"), builtin_registry());
  auto k0 = keys(base);
  EXPECT_EQ(k0.size(), 4u);  // sky, sh, specular, dfg
  for (const auto& [name, key] : k0) EXPECT_NE(key, 0u) << name;
  for (const char* name : {"gbuf/raster", "gtao/denoise", "ibl/shade"}) {
    int p = test::pass_at(base, name);
    ASSERT_GE(p, 0);
    EXPECT_FALSE(base.passes[p].is_static) << name;
    EXPECT_EQ(base.passes[p].cache_key, 0u) << name;
  }
  // Static outputs are cached; the rest of the frame is not.
  EXPECT_EQ(resource(base, "sky.cube").lifetime, ResourceLifetime::cached);
  EXPECT_EQ(resource(base, "sh.sh").lifetime, ResourceLifetime::cached);
  EXPECT_EQ(resource(base, "light.color").lifetime, ResourceLifetime::transient);

  // A sky param changes the keys of sky and everything fed by it, not the BRDF table's.
  Graph g = load_example("examples/default.json");
  test::node_named(g, "sky").params.set("turbidity", 5);
  auto k1 = keys(compile_ok(g, builtin_registry()));
  EXPECT_NE(k1["sky/render"], k0["sky/render"]);
  EXPECT_NE(k1["sh/project"], k0["sh/project"]);
  EXPECT_NE(k1["specular/prefilter"], k0["specular/prefilter"]);
  EXPECT_EQ(k1["dfg/integrate"], k0["dfg/integrate"]);

  // Writing a default explicitly is the same graph: the same keys.
  Graph same = load_example("examples/default.json");
  test::node_named(same, "dfg").params.set("size", 128);
  EXPECT_EQ(keys(compile_ok(same, builtin_registry())), k0);
}

// env.sky's static_unless param: a turning sun makes the sky, and every node it feeds, run each
// frame; the BRDF table, fed by nothing, stays cached.
TEST(CompilerLower, ATurningSunIsNotCachedNorIsWhatItFeeds) {
  Plan plan = compile_ok(load_example("examples/animated-sky.json"), builtin_registry());
  for (const char* name : {"sky/render", "sh/project", "specular/prefilter"}) {
    const int p = test::pass_at(plan, name);
    ASSERT_GE(p, 0) << name;
    EXPECT_FALSE(plan.passes[p].is_static) << name;
  }
  EXPECT_TRUE(plan.passes[test::pass_at(plan, "dfg/integrate")].is_static);
  EXPECT_EQ(resource(plan, "sky.cube").lifetime, ResourceLifetime::transient);
  // The same graph with the sun still: cached again.
  Graph still = load_example("examples/animated-sky.json");
  test::node_named(still, "sky").params.set("sun_turn_speed", 0);
  const Plan cached = compile_ok(still, builtin_registry());
  EXPECT_TRUE(cached.passes[test::pass_at(cached, "sky/render")].is_static);
  EXPECT_EQ(resource(cached, "sky.cube").lifetime, ResourceLifetime::cached);
}

TEST(CompilerLower, ABypassedNodeHasNoResourcesAndForwardsItsInputResource) {
  Plan plan = compile_ok(load_example("examples/post.json"), builtin_registry());
  for (const auto& r : plan.resources) EXPECT_FALSE(r.desc.name.starts_with("dof")) << r.desc.name;
  for (const auto& p : plan.passes) EXPECT_FALSE(p.name.starts_with("dof/")) << p.name;
  EXPECT_EQ(test::resource_name(plan, test::resource_in_slot(plan, "bloom/downsample", "in.color")), "ibl.color");
}

// lower() alone: a topological order from validate and the states from cull are all it needs.
TEST(CompilerLower, RunsAloneOnAnyTopologicalOrder) {
  Graph g = load_example("examples/default.json");
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  auto order = validate(r, {}, d);
  ASSERT_TRUE(order) << d.to_string();
  NodeStates states = cull(r, specialize(r, default_scene_summary()));
  auto lowered = lower(r, *order, states, {800, 600}, {}, d);
  ASSERT_TRUE(lowered) << d.to_string();
  // Passes come in the order of the nodes, each node's passes in schema order.
  std::vector<int> node_position(g.nodes.size());
  for (size_t k = 0; k < order->size(); ++k) node_position[(*order)[k]] = static_cast<int>(k);
  for (size_t p = 1; p < lowered->passes.size(); ++p) {
    const auto& a = lowered->passes[p - 1];
    const auto& b = lowered->passes[p];
    EXPECT_TRUE(node_position[a.node] < node_position[b.node] || (a.node == b.node && a.pass < b.pass))
        << a.name << " then " << b.name;
  }
  for (const auto& res : lowered->resources)
    if (res.name.starts_with("gbuf.")) {
      EXPECT_EQ(res.width, 800u) << res.name;
    }
}

}  // namespace
}  // namespace lg
