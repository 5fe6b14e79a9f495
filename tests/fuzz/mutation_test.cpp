// Graph files are untrusted input. Thousands of random mutations of the example graphs
// (flipped, inserted, deleted and duplicated bytes, truncations, spliced values) must each end
// in a plan or in errors that point into the file — never in a crash, a hang or silence.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/json_reader.h"
#include "graph/json_writer.h"
#include "nodes/builtin_schemas.h"

namespace lg {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Fragments that real mistakes and attacks put into graph files.
const char* const splices[] = {"NaN", "1e999", "-0", "null", "[]", "{}", "\"\"", "\"../../etc/passwd\"", "[[[[[[",
                               "\"a.b.c\"", "true", "99999999999999999999", "\"\\ud800\"", "\"\xff\xfe\"", ",", ":"};

std::string mutate(std::string text, std::mt19937_64& rng) {
  auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  int edits = 1 + static_cast<int>(pick(4));
  for (int e = 0; e < edits && !text.empty(); ++e) {
    size_t at = pick(text.size());
    switch (pick(6)) {
      case 0: text[at] = static_cast<char>(pick(256)); break;
      case 1: text.insert(at, 1, "{}[]\",:.0123456789eE-\\"[pick(22)]); break;
      case 2: text.erase(at, 1 + pick(8)); break;
      case 3: text.insert(at, text.substr(pick(text.size()), 1 + pick(40))); break;
      case 4: text.resize(at); break;
      default: text.insert(at, splices[pick(std::size(splices))]); break;
    }
  }
  return text;
}

// Compiles one mutated text: true when it gives a plan. A rejection must say why, and every
// error must carry a message and a line.
bool compiles(const std::string& text, const Registry& registry) {
  Diagnostics diagnostics("mutated.json");
  std::optional<Graph> graph = parse_graph_text(text, diagnostics);
  CompileResult result;
  if (graph) result = compile(*graph, registry, {}, diagnostics);
  if (result.plan) {
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.to_string();
    return true;
  }
  EXPECT_TRUE(diagnostics.has_errors()) << "rejected without a word:\n" << text;
  for (const Diagnostic& d : diagnostics.items())
    EXPECT_TRUE(d.pos.line > 0 && !d.message.empty()) << d.to_string() << "\nin:\n" << text;
  return false;
}

void collect(JsonValue& v, std::vector<JsonValue*>& out) {
  out.push_back(&v);
  for (auto& item : v.items()) collect(item, out);
  for (auto& [key, member] : v.members()) collect(member, out);
}

// Values that are valid JSON but wrong in a graph: they reach validation and lowering.
JsonValue random_value(std::mt19937_64& rng, const std::vector<std::string>& words) {
  auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  switch (pick(7)) {
    case 0: return JsonValue(std::uniform_real_distribution<double>(-1e6, 1e6)(rng));
    case 1: return JsonValue(static_cast<int64_t>(pick(5000)) - 10);
    case 2: return JsonValue(words[pick(words.size())]);
    case 3: return JsonValue(words[pick(words.size())] + "." + words[pick(words.size())]);
    case 4: {
      JsonValue a = JsonValue::array();
      for (size_t k = pick(5); k > 0; --k) a.push(JsonValue(static_cast<int64_t>(pick(70000))));
      return a;
    }
    case 5: return JsonValue(pick(2) == 0);
    default: return JsonValue();
  }
}

// Structural edits of a valid graph: replace a value, drop or duplicate an item or member.
void mutate_structure(JsonValue& root, std::mt19937_64& rng, const std::vector<std::string>& words) {
  auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  std::vector<JsonValue*> values;
  collect(root, values);
  JsonValue& target = *values[pick(values.size())];
  switch (pick(3)) {
    case 0: target = random_value(rng, words); break;
    case 1:
      if (target.is_array() && !target.items().empty()) target.items().erase(target.items().begin() + pick(target.items().size()));
      else if (target.is_object() && !target.members().empty()) target.members().erase(target.members().begin() + pick(target.members().size()));
      break;
    default:
      if (target.is_array() && !target.items().empty()) target.items().push_back(target.items()[pick(target.items().size())]);
      break;
  }
}

TEST(FuzzGraphMutation, StructuralEditsEndInAPlanOrLocatedErrors) {
  const Registry& registry = builtin_registry();
  std::vector<std::string> words = {"gbuf", "sky", "sh", "tonemap", "out", "color", "cube", "env", "gbuffer", "ao",
                                    "history", "lumagraph/1", "../x.hdr", "sky.hdr", "hanning", "aces_fitted"};
  for (const NodeSchema* s : registry.all()) words.push_back(s->type);
  std::mt19937_64 rng(7);
  size_t plans = 0, rejected = 0;
  for (const auto& entry : std::filesystem::directory_iterator("examples")) {
    if (entry.path().extension() != ".json") continue;
    Diagnostics read_diagnostics;
    std::optional<JsonValue> original = read_json(read_text(entry.path()), read_diagnostics);
    ASSERT_TRUE(original) << read_diagnostics.to_string();
    for (int round = 0; round < 1500; ++round) {
      JsonValue root = *original;
      for (size_t edits = 1 + round % 3; edits > 0; --edits) mutate_structure(root, rng, words);
      (compiles(write_json(root), registry) ? plans : rejected) += 1;
      if (testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(plans, 500u);
  EXPECT_GT(rejected, 1000u);
  std::printf("structural mutations compiled: %zu, rejected with errors: %zu\n", plans, rejected);
}

TEST(FuzzGraphMutation, EveryMutationEndsInAPlanOrLocatedErrors) {
  const Registry& registry = builtin_registry();
  std::mt19937_64 rng(20261122);
  size_t plans = 0, rejected = 0;
  for (const auto& entry : std::filesystem::directory_iterator("examples")) {
    if (entry.path().extension() != ".json") continue;
    const std::string original = read_text(entry.path());
    for (int round = 0; round < 1500; ++round) {
      (compiles(mutate(original, rng), registry) ? plans : rejected) += 1;
      if (testing::Test::HasFailure()) return;
    }
  }
  // Both outcomes must occur, or the mutations are too weak (or too strong) to test anything.
  EXPECT_GT(plans, 10u);
  EXPECT_GT(rejected, 1000u);
  std::printf("mutations compiled: %zu, rejected with errors: %zu\n", plans, rejected);
}

}  // namespace
}  // namespace lg
