// A node type described as data: typed ports, parameters (type, default, range or enum, unit,
// doc), internal resources, the passes it lowers to and what each pass reads and writes, the
// scene features it needs and the rules that bypass it. Each node folder under nodes/ holds one
// schema.json; this is the single source for validation, lowering, the editor and `nodes --json`.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "graph/json_value.h"
#include "graph/port_type.h"
#include "graph/scene_summary.h"

namespace lg {

enum class ParamType : uint8_t { float_, int_, bool_, enum_, string, path, float2, float3, float4, int2 };
std::string_view param_type_name(ParamType t);
size_t param_components(ParamType t);  // 1 for scalars, N for vectors, 0 for non-numeric

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::float_;
  JsonValue default_value;
  std::optional<double> min, max;       // per component for vectors
  std::vector<std::string> values;      // enum choices
  std::vector<double> choices;          // float and int params: where given, the only values allowed
  std::vector<std::string> extensions;  // path params: accepted file extensions
  int less_than = -1;                   // float and int params: a param whose value this one must stay below
  std::string unit, doc;
};

// How big a resource is. Extents come from the frame, an input, a parameter or a constant,
// then scale; cube maps use the width as the face size; a 3D texture's depth from a parameter or
// a constant ("depth"), not scaled.
struct SizeRule {
  enum class From : uint8_t { frame, input, param, fixed } from = From::frame;
  int ref = -1;  // input or param index
  std::array<uint32_t, 2> fixed{1, 1};
  double scale = 1;
  int scale_param = -1;
  bool only_when_scaled = false;  // a 1x1 placeholder (bound, never used) while scale_param is 1
  enum class Mips : uint8_t { one, full, param, fixed } mips = Mips::one;
  int mips_param = -1;
  uint32_t mips_fixed = 1;
  int sh_order_param = -1;  // "sh" buffers: (order + 1)^2 coefficients
  int depth_param = -1;     // texture3d: the depth in a number param, or
  uint32_t depth_fixed = 1;  // a constant
};

struct PortSpec {
  std::string name;
  PortType type;
  std::string doc;
  // inputs: may stay unlinked; outputs: written only while linked or kept (a debug view, such as
  // gi.lpv's volume: unlinked, the plan drops its accesses, so the kernel skips it)
  bool optional = false;
  bool history = false;   // inputs: reads the previous frame; the only legal back edge
  SizeRule size;          // outputs and internal resources
};

enum class Usage : uint8_t {
  sampled,             // read through a sampler
  storage_read,        // read as a storage image
  storage_write,       // written as a storage image
  storage_read_write,  // read and written as a storage image
  attachment_write,    // render target (colour or depth by format), cleared and written
  attachment_blend,    // render target, loaded and blended onto
  buffer_read,
  buffer_write,
};
std::string_view usage_name(Usage u);
std::optional<Usage> parse_usage(std::string_view name);
// Inline: the compiler asks both for every access of every pass.
inline bool usage_writes(Usage u) {
  return u == Usage::storage_write || u == Usage::storage_read_write || u == Usage::attachment_write ||
         u == Usage::attachment_blend || u == Usage::buffer_write;
}
inline bool usage_reads(Usage u) {
  return u == Usage::sampled || u == Usage::storage_read || u == Usage::storage_read_write ||
         u == Usage::attachment_blend || u == Usage::buffer_read;
}

enum class Queue : uint8_t { graphics, compute };

struct PassUse {
  enum class Target : uint8_t { input, output, internal } target = Target::input;
  int index = 0;
  int component = -1;  // one component of a bundle ("in.gbuffer.depth"), or -1 for all
  Usage usage = Usage::sampled;
};

struct PassSpec {
  std::string name;
  Queue queue = Queue::compute;
  std::optional<SceneFeature> needs;  // the pass is dropped when the scene lacks this
  std::vector<PassUse> uses;
  std::string doc;
};

struct Condition {
  enum class Kind : uint8_t { scene_lacks, param_equals, param_at_most } kind = Kind::scene_lacks;
  SceneFeature feature = SceneFeature::count;
  int param = -1;
  JsonValue value;
  std::vector<int> unless_linked;  // inputs: the rule does not hold while any of them is linked
};

struct BypassRule {
  Condition when;
  // output index <- input index, or -1: the output holds nothing and its consumers' optional
  // inputs stay unlinked (a required input fed by it is an error)
  std::vector<std::pair<int, int>> forward;
  std::string reason;
};

// Inputs an active node cannot run without in some configurations: when `when` holds (if given)
// and the scene has `scene_has` (if given), every group of `linked` needs one of its inputs fed
// after specialization; the compiler refuses the graph otherwise, naming the node and inputs.
struct LinkRequirement {
  std::optional<Condition> when;
  std::optional<SceneFeature> scene_has;
  std::vector<std::vector<int>> linked;  // each group: any one of these inputs
  std::string reason;                    // why, for the message
};

// A named set of param values that trades time for error (the editor offers them as one edit);
// `doc` says what the choice costs and buys, with the benchmark numbers behind it.
struct ParamPreset {
  std::string name, doc;
  std::vector<std::pair<int, JsonValue>> values;  // param index, value (valid for that param)
};

struct NodeSchema {
  std::string type;      // "post.bloom"
  std::string category;  // "post"
  std::string doc;
  std::string file;  // where the schema came from, for messages
  std::vector<PortSpec> inputs, outputs, resources;
  std::vector<ParamSpec> params;
  std::vector<PassSpec> passes;
  std::vector<BypassRule> bypass;
  std::vector<LinkRequirement> requires_linked;
  std::vector<ParamPreset> presets;
  bool is_static = false;  // result depends only on params and static inputs: cached across frames
  // A number param that, when not 0, makes a static node run every frame (env.sky's sun turning
  // with time); -1: none.
  int static_unless_param = -1;
  bool is_output = false;  // a sink: its inputs are results of the frame
  // An input whose pixel grid the camera is jittered on, sub-pixel, while the node runs
  // (temporal anti-aliasing: runtime/scene/camera_jitter.h); -1: the node needs no jitter.
  int camera_jitter_input = -1;

  int find_input(std::string_view name) const;
  int find_output(std::string_view name) const;
  int find_param(std::string_view name) const;
};

}  // namespace lg
