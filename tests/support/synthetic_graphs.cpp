#include "tests/support/synthetic_graphs.h"

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace lg::test {
namespace {

const char* const schemas[] = {
    R"({ "type": "test.source", "doc": "A 2D image from nothing.",
         "params": [ { "name": "size", "type": "int2", "default": [256, 256], "min": 1, "max": 4096, "doc": "Extent." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "param:size", "doc": "Image." } ],
         "passes": [ { "name": "make", "queue": "compute", "uses": { "out.out": "storage_write" } } ] })",
    R"({ "type": "test.env", "doc": "A static cube map.", "static": true,
         "params": [ { "name": "face", "type": "int", "default": 64, "min": 1, "max": 1024, "doc": "Face size." } ],
         "outputs": [ { "name": "out", "type": "cube:hdr", "extent": "param:face", "mips": "full", "doc": "Cube." } ],
         "passes": [ { "name": "make", "queue": "compute", "uses": { "out.out": "storage_write" } } ] })",
    R"({ "type": "test.raster", "doc": "A G-buffer bundle, rasterized.",
         "outputs": [ { "name": "out", "type": "gbuffer", "extent": "frame", "doc": "Bundle." } ],
         "passes": [ { "name": "draw", "queue": "graphics", "uses": { "out.out": "attachment_write" } } ] })",
    R"({ "type": "test.filter", "doc": "Two passes through a half-size temporary.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "Input." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Output." } ],
         "resources": [ { "name": "half", "type": "texture2d:hdr", "extent": "input:a", "scale": 0.5, "doc": "Temp." } ],
         "passes": [
           { "name": "down", "queue": "compute", "uses": { "in.a": "sampled", "tmp.half": "storage_write" } },
           { "name": "up", "queue": "compute", "uses": { "tmp.half": "sampled", "in.a": "storage_read", "out.out": "storage_write" } } ] })",
    R"({ "type": "test.blend", "doc": "Draws two images into a render target, then blends a third.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "A." }, { "name": "b", "type": "texture2d:hdr", "doc": "B." },
                     { "name": "c", "type": "texture2d:hdr", "optional": true, "doc": "C." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Output." } ],
         "passes": [
           { "name": "draw", "queue": "graphics", "uses": { "in.a": "sampled", "in.b": "sampled", "out.out": "attachment_write" } },
           { "name": "add", "queue": "graphics", "uses": { "in.c": "sampled", "out.out": "attachment_blend" } } ] })",
    R"({ "type": "test.shade", "doc": "Reads parts of a G-buffer and an image.",
         "inputs": [ { "name": "g", "type": "gbuffer", "doc": "Bundle." }, { "name": "a", "type": "texture2d:hdr", "doc": "Image." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:g", "doc": "Output." } ],
         "passes": [ { "name": "shade", "queue": "compute",
                       "uses": { "in.g.depth": "sampled", "in.g.normal": "sampled", "in.a": "sampled", "out.out": "storage_write" } },
                     { "name": "refine", "queue": "compute", "uses": { "in.g.motion": "sampled", "out.out": "storage_read_write" } } ] })",
    R"({ "type": "test.reduce", "doc": "Reduces an image to a buffer.",
         "params": [ { "name": "order", "type": "int", "default": 2, "min": 0, "max": 8, "doc": "Order." } ],
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "Image." } ],
         "outputs": [ { "name": "out", "type": "sh", "sh_order": "param:order", "doc": "Buffer." } ],
         "passes": [ { "name": "sum", "queue": "compute", "uses": { "in.a": "sampled", "out.out": "buffer_write" } } ] })",
    R"({ "type": "test.apply", "doc": "Applies a buffer and a cube to an image.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "Image." }, { "name": "s", "type": "sh", "doc": "Buffer." },
                     { "name": "e", "type": "cube:hdr", "optional": true, "doc": "Cube." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Output." } ],
         "passes": [ { "name": "apply", "queue": "compute",
                       "uses": { "in.a": "sampled", "in.s": "buffer_read", "in.e": "sampled", "out.out": "storage_write" } } ] })",
    R"({ "type": "test.temporal", "doc": "Blends an image with its own previous frame.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "Image." },
                     { "name": "history", "type": "texture2d:hdr", "optional": true, "history": true, "doc": "Last frame." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Output." } ],
         "passes": [ { "name": "blend", "queue": "compute", "uses": { "in.a": "sampled", "in.history": "sampled", "out.out": "storage_write" } } ] })",
    R"({ "type": "test.sink", "doc": "A result of the frame.", "output": true,
         "inputs": [ { "name": "color", "type": "texture2d:*", "doc": "Result." } ] })",
};

void link(Graph& g, const std::string& from, const std::string& to) {
  auto split = [](const std::string& s) {
    size_t dot = s.find('.');
    return PortRef{s.substr(0, dot), s.substr(dot + 1)};
  };
  g.links.push_back({split(from), split(to), {}, {}});
}

GraphNode node(std::string id, std::string type) {
  GraphNode n;
  n.id = std::move(id);
  n.type = std::move(type);
  return n;
}

}  // namespace

const Registry& synthetic_registry() {
  static const Registry registry = [] {
    Registry r;
    for (const char* text : schemas) {
      Diagnostics d("synthetic schema");
      if (!r.add_schema(text, d)) {
        std::fputs(d.to_string().c_str(), stderr);
        std::abort();
      }
    }
    return r;
  }();
  return registry;
}

Graph make_chain(size_t nodes) {
  Graph g;
  g.name = "chain-" + std::to_string(nodes);
  g.nodes.push_back(node("n0", "test.source"));
  for (size_t k = 1; k + 1 < nodes; ++k) {
    g.nodes.push_back(node("n" + std::to_string(k), "test.filter"));
    link(g, "n" + std::to_string(k - 1) + ".out", "n" + std::to_string(k) + ".a");
  }
  g.nodes.push_back(node("sink", "test.sink"));
  link(g, "n" + std::to_string(nodes - 2) + ".out", "sink.color");
  return g;
}

Graph make_random_dag(const RandomDagOptions& o) {
  std::mt19937_64 rng(o.seed);
  auto chance = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; };
  auto pick = [&](size_t n) { return static_cast<size_t>(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };

  Graph g;
  g.name = "random-" + std::to_string(o.nodes);
  // Outputs made so far, by port type: every output reads from the last `window` of its kind.
  // A live node's side products (a G-buffer, a buffer, a cube, a second image) wait in
  // `pending` until the next live node of a matching type consumes them, so every node meant
  // to be live reaches the sink and lifetimes stay local, as in real frame graphs.
  enum Kind { image, gbuffer, buffer, cube, kinds };
  std::vector<std::string> made[kinds], made_live[kinds], pending[kinds];
  std::string backbone;  // the newest live image; each live image node extends it
  auto recent_in = [&](const std::vector<std::string>& list) -> std::string {
    if (list.empty()) return {};
    return list[list.size() - 1 - pick(std::min(o.window, list.size()))];
  };
  auto recent = [&](Kind k) { return recent_in(made[k]); };
  auto take = [&](Kind k) -> std::string {
    if (pending[k].empty()) return recent_in(made_live[k]);
    std::string port = pending[k].front();
    pending[k].erase(pending[k].begin());
    return port;
  };

  for (size_t k = 0; k + 1 < o.nodes; ++k) {
    std::string id = "n" + std::to_string(k);
    bool live = backbone.empty() || !chance(o.dead_fraction);
    std::string type;
    if (backbone.empty()) type = "test.source";
    else if (live && !pending[gbuffer].empty()) type = "test.shade";
    else if (live && (!pending[buffer].empty() || (!pending[cube].empty() && !made_live[buffer].empty()))) type = "test.apply";
    else if (live && !pending[cube].empty()) type = "test.reduce";
    else if (live && !pending[image].empty()) type = "test.blend";
    else {
      static const char* const choices[] = {"test.filter", "test.filter", "test.blend", "test.temporal", "test.source",
                                            "test.env",    "test.raster", "test.reduce", "test.shade",   "test.apply"};
      type = choices[pick(std::size(choices))];
      const auto& gbuffers = live ? made_live[gbuffer] : made[gbuffer];
      const auto& buffers = live ? made_live[buffer] : made[buffer];
      if ((type == "test.shade" && gbuffers.empty()) || (type == "test.apply" && buffers.empty())) type = "test.filter";
    }
    // Live nodes read the live backbone; dead ones read anything recent.
    auto input = [&](Kind kind) { return live ? take(kind) : recent(kind); };
    auto other_image = [&] { return live ? recent_in(made_live[image]) : recent(image); };
    std::string main_image = live ? backbone : recent(image);

    GraphNode n = node(id, type);
    if (type == "test.source") {
      JsonValue size = JsonValue::array();
      size.push(static_cast<int64_t>(64 + pick(961)));
      size.push(static_cast<int64_t>(64 + pick(961)));
      n.params.set("size", size);
    }
    g.nodes.push_back(std::move(n));
    if (type == "test.filter" || type == "test.reduce" || type == "test.temporal") link(g, main_image, id + ".a");
    if (type == "test.blend") {
      link(g, main_image, id + ".a");
      link(g, live && !pending[image].empty() ? take(image) : other_image(), id + ".b");
      if (chance(0.5)) link(g, other_image(), id + ".c");
    }
    if (type == "test.shade") link(g, input(gbuffer), id + ".g"), link(g, main_image, id + ".a");
    if (type == "test.apply") {
      link(g, main_image, id + ".a");
      link(g, input(buffer), id + ".s");
      if (!(live ? made_live[cube] : made[cube]).empty() && (!pending[cube].empty() || chance(0.5))) link(g, input(cube), id + ".e");
    }
    if (type == "test.temporal" && chance(o.history_fraction)) link(g, id + ".out", id + ".history");

    std::string out = id + ".out";
    Kind kind = type == "test.env" ? cube : type == "test.raster" ? gbuffer : type == "test.reduce" ? buffer : image;
    made[kind].push_back(out);
    if (live) made_live[kind].push_back(out);
    bool extends_backbone = kind == image && (type != "test.source" || backbone.empty());
    if (live && extends_backbone) backbone = out;
    else if (live) pending[kind].push_back(out);
  }
  g.nodes.push_back(node("sink", "test.sink"));
  link(g, backbone, "sink.color");
  return g;
}

}  // namespace lg::test
