#include "graph/schema_reader.h"

#include <cmath>
#include <functional>
#include <span>

#include "graph/compiler/validate.h"
#include "graph/json_reader.h"

namespace lg {
namespace {

class SchemaReader {
 public:
  SchemaReader(NodeSchema& schema, Diagnostics& d) : s_(schema), d_(d) {}

  void read(const JsonValue& root) {
    if (!expect_object(root, "")) return;
    check_keys(root, "",
               {"type", "doc", "static", "static_unless", "output", "camera_jitter", "inputs", "outputs", "resources",
                "params", "passes", "bypass", "requires", "presets"});
    s_.type = string_at(root, "", "type", true);
    s_.category = s_.type.substr(0, s_.type.find('.'));
    s_.doc = string_at(root, "", "doc", true);
    s_.is_static = bool_at(root, "", "static");
    s_.is_output = bool_at(root, "", "output");
    each(root, "params", [&](const JsonValue& v, const std::string& p) { param(v, p); });
    if (const JsonValue* params = root.find("params"); params && params->is_array())
      for (size_t k = 0; k < params->items().size(); ++k)
        ordering(params->items()[k], json_pointer_append("/params", k));
    static_unless(root);
    each(root, "presets", [&](const JsonValue& v, const std::string& p) { preset(v, p); });
    each(root, "inputs", [&](const JsonValue& v, const std::string& p) { s_.inputs.push_back(port(v, p, Role::input)); });
    camera_jitter(root);
    each(root, "outputs", [&](const JsonValue& v, const std::string& p) { s_.outputs.push_back(port(v, p, Role::output)); });
    each(root, "resources",
         [&](const JsonValue& v, const std::string& p) { s_.resources.push_back(port(v, p, Role::resource)); });
    each(root, "passes", [&](const JsonValue& v, const std::string& p) { pass(v, p); });
    each(root, "bypass", [&](const JsonValue& v, const std::string& p) { bypass(v, p); });
    each(root, "requires", [&](const JsonValue& v, const std::string& p) { requirement(v, p); });
    if (s_.passes.empty() && !s_.is_output) d_.error(root.pos(), "/passes", "a node needs at least one pass");
  }

 private:
  NodeSchema& s_;
  Diagnostics& d_;

  bool expect_object(const JsonValue& v, const std::string& p) {
    if (v.is_object()) return true;
    d_.error(v.pos(), p, std::string("expected an object, found ") + JsonValue::kind_name(v.kind()));
    return false;
  }

  void check_keys(const JsonValue& obj, const std::string& p, std::initializer_list<std::string_view> known) {
    for (const auto& [k, v] : obj.members()) {
      bool ok = false;
      for (auto name : known) ok |= name == k;
      if (!ok) d_.error(v.pos(), json_pointer_append(p, k), "unknown key '" + k + "'");
    }
  }

  std::string string_at(const JsonValue& obj, const std::string& p, std::string_view key, bool required) {
    const JsonValue* v = obj.find(key);
    if (!v) {
      if (required) d_.error(obj.pos(), p, "missing \"" + std::string(key) + "\"");
      return {};
    }
    if (!v->is_string()) {
      d_.error(v->pos(), json_pointer_append(p, key), "expected a string");
      return {};
    }
    return v->as_string();
  }

  bool bool_at(const JsonValue& obj, const std::string& p, std::string_view key) {
    const JsonValue* v = obj.find(key);
    if (!v) return false;
    if (!v->is_bool()) d_.error(v->pos(), json_pointer_append(p, key), "expected true or false");
    return v->is_bool() && v->as_bool();
  }

  void each(const JsonValue& obj, std::string_view key, const std::function<void(const JsonValue&, const std::string&)>& f) {
    const JsonValue* list = obj.find(key);
    if (!list) return;
    std::string p = json_pointer_append("", key);
    if (!list->is_array()) {
      d_.error(list->pos(), p, "expected an array");
      return;
    }
    for (size_t k = 0; k < list->items().size(); ++k) {
      const JsonValue& item = list->items()[k];
      std::string ip = json_pointer_append(p, k);
      if (expect_object(item, ip)) f(item, ip);
    }
  }

  // "param:NAME" -> param index, or -1 with an error.
  int param_ref(const JsonValue& v, const std::string& p) {
    std::string text = v.as_string().substr(6);
    int index = s_.find_param(text);
    if (index < 0) d_.error(v.pos(), p, "no param named '" + text + "' (params must come before their use)");
    return index;
  }

  bool is_ref(const JsonValue& v, std::string_view prefix) {
    return v.is_string() && v.as_string().rfind(prefix, 0) == 0;
  }

  void param(const JsonValue& v, const std::string& p) {
    check_keys(v, p, {"name", "type", "default", "min", "max", "values", "extensions", "less_than", "unit", "doc"});
    ParamSpec spec;
    spec.name = string_at(v, p, "name", true);
    std::string type = string_at(v, p, "type", true);
    bool known = false;
    for (int t = 0; t <= static_cast<int>(ParamType::int2); ++t)
      if (param_type_name(static_cast<ParamType>(t)) == type) {
        spec.type = static_cast<ParamType>(t);
        known = true;
      }
    if (!known) d_.error(v.pos(), json_pointer_append(p, "type"), "unknown param type '" + type + "'");
    spec.doc = string_at(v, p, "doc", true);
    spec.unit = string_at(v, p, "unit", false);
    for (auto key : {"min", "max"}) {
      if (const JsonValue* b = v.find(key)) {
        if (b->is_number()) (std::string_view(key) == "min" ? spec.min : spec.max) = b->as_number();
        else d_.error(b->pos(), json_pointer_append(p, key), "expected a number");
      }
    }
    // "values": an enum's names, or the numbers a float or int param may take.
    const bool numeric = spec.type == ParamType::float_ || spec.type == ParamType::int_;
    if (const JsonValue* b = v.find("values"); b && numeric) {
      for (const auto& item : b->items()) {
        if (item.is_number()) spec.choices.push_back(item.as_number());
        else d_.error(item.pos(), json_pointer_append(p, "values"), "expected numbers");
      }
    }
    for (auto [key, list] : {std::pair{"values", &spec.values}, std::pair{"extensions", &spec.extensions}}) {
      if (const JsonValue* b = v.find(key); b && !(numeric && list == &spec.values)) {
        for (const auto& item : b->items()) {
          if (item.is_string()) list->push_back(item.as_string());
          else d_.error(item.pos(), json_pointer_append(p, key), "expected strings");
        }
      }
    }
    if (spec.type == ParamType::enum_ && spec.values.empty())
      d_.error(v.pos(), p, "an enum param needs \"values\"");
    if (const JsonValue* def = v.find("default")) spec.default_value = *def;
    else d_.error(v.pos(), p, "missing \"default\"");
    s_.params.push_back(std::move(spec));
  }

  static bool numeric_scalar(const ParamSpec& spec) {
    return spec.type == ParamType::float_ || spec.type == ParamType::int_;
  }

  // "less_than": NAME, once every param is read (the other may come later): both params numbers,
  // and the defaults in that order, so a graph that sets neither is valid.
  void ordering(const JsonValue& v, const std::string& p) {
    const JsonValue* other = v.is_object() ? v.find("less_than") : nullptr;
    if (!other) return;
    const std::string lp = json_pointer_append(p, "less_than");
    const JsonValue* name = v.find("name");
    const int self = name && name->is_string() ? s_.find_param(name->as_string()) : -1;
    const int index = other->is_string() ? s_.find_param(other->as_string()) : -1;
    if (self < 0 || index < 0 || index == self || !numeric_scalar(s_.params[size_t(self)]) ||
        !numeric_scalar(s_.params[size_t(index)])) {
      d_.error(other->pos(), lp, "expected the name of another float or int param, on a float or int param");
      return;
    }
    ParamSpec& spec = s_.params[size_t(self)];
    const JsonValue &mine = spec.default_value, &theirs = s_.params[size_t(index)].default_value;
    if (mine.is_number() && theirs.is_number() && !(mine.as_number() < theirs.as_number()))
      d_.error(other->pos(), lp, "the default must be below '" + other->as_string() + "''s default");
    spec.less_than = index;
  }

  // {"name", "doc", "params": {PARAM: VALUE, ...}}: each value valid for its param, names unique.
  void preset(const JsonValue& v, const std::string& p) {
    check_keys(v, p, {"name", "doc", "params"});
    ParamPreset preset;
    preset.name = string_at(v, p, "name", true);
    preset.doc = string_at(v, p, "doc", true);
    for (const ParamPreset& other : s_.presets)
      if (!preset.name.empty() && other.name == preset.name)
        d_.error(v.find("name")->pos(), json_pointer_append(p, "name"), "a second preset named '" + preset.name + "'");
    const JsonValue* params = v.find("params");
    const std::string pp = json_pointer_append(p, "params");
    if (!params || !params->is_object() || params->members().empty()) {
      d_.error(params ? params->pos() : v.pos(), pp, "expected an object of param values, at least one");
    } else {
      for (const auto& [name, value] : params->members()) {
        const int index = s_.find_param(name);
        if (index < 0) {
          d_.error(value.pos(), json_pointer_append(pp, name), "no param named '" + name + "'");
        } else if (std::string expected = check_param_value(s_.params[index], value); !expected.empty()) {
          d_.error(value.pos(), json_pointer_append(pp, name), "expected " + expected);
        } else {
          preset.values.emplace_back(index, value);
        }
      }
    }
    s_.presets.push_back(std::move(preset));
  }

  enum class Role { input, output, resource };

  PortSpec port(const JsonValue& v, const std::string& p, Role role) {
    const bool is_input = role == Role::input;
    check_keys(v, p, {"name", "type", "doc", "optional", "history", "extent", "scale", "only_when_scaled", "mips",
                       "sh_order", "depth"});
    PortSpec spec;
    spec.name = string_at(v, p, "name", true);
    spec.doc = string_at(v, p, "doc", true);
    std::string why;
    auto type = parse_port_type(string_at(v, p, "type", true), is_input, &why);
    if (type) spec.type = *type;
    else d_.error(v.pos(), json_pointer_append(p, "type"), why);
    spec.optional = bool_at(v, p, "optional");
    spec.history = bool_at(v, p, "history");
    if (!is_input) size_rule(v, p, spec.size);
    if (!is_input && type) depth_rule(v, p, spec);
    // A placeholder is for what the node alone reads: an output would hand its consumers a 1x1 image.
    if (const JsonValue* placeholder = v.find("only_when_scaled"); placeholder && role != Role::resource)
      d_.error(placeholder->pos(), json_pointer_append(p, "only_when_scaled"),
               "only a resource can be a placeholder at scale 1, not an input or an output");
    return spec;
  }

  // "static_unless": "param:NAME": a static node runs every frame while that number param is not 0.
  void static_unless(const JsonValue& root) {
    const JsonValue* v = root.find("static_unless");
    if (!v) return;
    if (!s_.is_static) d_.error(v->pos(), "/static_unless", "only a static node (\"static\": true) can have one");
    if (!is_ref(*v, "param:")) {
      d_.error(v->pos(), "/static_unless", "expected \"param:NAME\"");
      return;
    }
    s_.static_unless_param = param_ref(*v, "/static_unless");
    if (s_.static_unless_param >= 0 && !numeric_scalar(s_.params[size_t(s_.static_unless_param)])) {
      d_.error(v->pos(), "/static_unless", "'" + v->as_string().substr(6) + "' is not a number param");
      s_.static_unless_param = -1;
    }
  }

  // "camera_jitter": "INPUT": the node asks for a jittered camera on that input's pixel grid.
  void camera_jitter(const JsonValue& root) {
    const std::string input = string_at(root, "", "camera_jitter", false);
    if (input.empty()) return;
    s_.camera_jitter_input = s_.find_input(input);
    if (s_.camera_jitter_input < 0)
      d_.error(root.find("camera_jitter")->pos(), "/camera_jitter", "no input named '" + input + "'");
  }

  void size_rule(const JsonValue& v, const std::string& p, SizeRule& r) {
    if (const JsonValue* e = v.find("extent")) {
      std::string ep = json_pointer_append(p, "extent");
      if (is_ref(*e, "frame")) {
        r.from = SizeRule::From::frame;
      } else if (is_ref(*e, "input:")) {
        r.from = SizeRule::From::input;
        r.ref = s_.find_input(e->as_string().substr(6));
        if (r.ref < 0) d_.error(e->pos(), ep, "no input named '" + e->as_string().substr(6) + "'");
      } else if (is_ref(*e, "param:")) {
        r.from = SizeRule::From::param;
        r.ref = param_ref(*e, ep);
      } else if (e->is_array() && e->items().size() == 2 && e->items()[0].is_integer() && e->items()[1].is_integer()) {
        r.from = SizeRule::From::fixed;
        r.fixed = {static_cast<uint32_t>(e->items()[0].as_number()), static_cast<uint32_t>(e->items()[1].as_number())};
      } else {
        d_.error(e->pos(), ep, "expected \"frame\", \"input:NAME\", \"param:NAME\" or [width, height]");
      }
    }
    if (const JsonValue* s = v.find("scale")) {
      if (s->is_number()) r.scale = s->as_number();
      else if (is_ref(*s, "param:")) r.scale_param = param_ref(*s, json_pointer_append(p, "scale"));
      else d_.error(s->pos(), json_pointer_append(p, "scale"), "expected a number or \"param:NAME\"");
    }
    r.only_when_scaled = bool_at(v, p, "only_when_scaled");
    if (r.only_when_scaled && r.scale_param < 0)
      d_.error(v.find("only_when_scaled")->pos(), json_pointer_append(p, "only_when_scaled"),
               "needs \"scale\": \"param:NAME\" (the param whose value 1 leaves the resource unused)");
    if (const JsonValue* m = v.find("mips")) {
      if (m->is_string() && m->as_string() == "full") {
        r.mips = SizeRule::Mips::full;
      } else if (is_ref(*m, "param:")) {
        r.mips = SizeRule::Mips::param;
        r.mips_param = param_ref(*m, json_pointer_append(p, "mips"));
      } else if (m->is_integer() && m->as_number() >= 1) {
        r.mips = SizeRule::Mips::fixed;
        r.mips_fixed = static_cast<uint32_t>(m->as_number());
      } else {
        d_.error(m->pos(), json_pointer_append(p, "mips"), "expected \"full\", a count or \"param:NAME\"");
      }
    }
    if (const JsonValue* o = v.find("sh_order")) {
      if (is_ref(*o, "param:")) r.sh_order_param = param_ref(*o, json_pointer_append(p, "sh_order"));
      else d_.error(o->pos(), json_pointer_append(p, "sh_order"), "expected \"param:NAME\"");
    }
  }

  // "depth": a count or "param:NAME" (a number param), which a 3D texture needs and only it has.
  void depth_rule(const JsonValue& v, const std::string& p, PortSpec& spec) {
    const JsonValue* d = v.find("depth");
    const bool is_3d = spec.type.resource == ResourceKind::texture3d;
    if (!d) {
      if (is_3d) d_.error(v.pos(), p, "a 3D texture needs \"depth\": a count or \"param:NAME\"");
      return;
    }
    const std::string dp = json_pointer_append(p, "depth");
    if (!is_3d) {
      d_.error(d->pos(), dp, "only a 3D texture (texture3d) has a depth, not " + spec.type.kind);
    } else if (is_ref(*d, "param:")) {
      spec.size.depth_param = param_ref(*d, dp);
      if (spec.size.depth_param >= 0 && !numeric_scalar(s_.params[size_t(spec.size.depth_param)])) {
        d_.error(d->pos(), dp, "'" + d->as_string().substr(6) + "' is not a number param");
        spec.size.depth_param = -1;
      }
    } else if (d->is_integer() && d->as_number() >= 1 && d->as_number() <= 65536) {
      spec.size.depth_fixed = static_cast<uint32_t>(d->as_number());
    } else {
      d_.error(d->pos(), dp, "expected a count from 1 to 65536 or \"param:NAME\"");
    }
  }

  void pass(const JsonValue& v, const std::string& p) {
    check_keys(v, p, {"name", "queue", "needs", "uses", "doc"});
    PassSpec spec;
    spec.name = string_at(v, p, "name", true);
    spec.doc = string_at(v, p, "doc", false);
    std::string queue = string_at(v, p, "queue", true);
    if (queue == "graphics") spec.queue = Queue::graphics;
    else if (queue == "compute") spec.queue = Queue::compute;
    else d_.error(v.pos(), json_pointer_append(p, "queue"), "expected \"graphics\" or \"compute\"");
    if (v.find("needs")) {
      std::string needs = string_at(v, p, "needs", false);
      spec.needs = parse_scene_feature(needs);
      if (!spec.needs) d_.error(v.find("needs")->pos(), json_pointer_append(p, "needs"), "unknown scene feature '" + needs + "'");
    }
    const JsonValue* uses = v.find("uses");
    if (!uses || !uses->is_object()) {
      d_.error(v.pos(), p, "missing \"uses\": {\"in.NAME\": \"sampled\", \"out.NAME\": \"storage_write\", ...}");
    } else {
      for (const auto& [target, usage] : uses->members()) {
        std::string up = json_pointer_append(json_pointer_append(p, "uses"), target);
        PassUse use;
        size_t dot = target.find('.'), second = target.find('.', dot == std::string::npos ? dot : dot + 1);
        std::string scope = target.substr(0, dot);
        std::string name = dot == std::string::npos ? "" : target.substr(dot + 1, second - dot - 1);
        std::string component = second == std::string::npos ? "" : target.substr(second + 1);
        const PortSpec* port = nullptr;
        if (scope == "in") use.target = PassUse::Target::input, use.index = s_.find_input(name);
        else if (scope == "out") use.target = PassUse::Target::output, use.index = s_.find_output(name);
        else if (scope == "tmp") use.target = PassUse::Target::internal, use.index = [&] {
          for (size_t k = 0; k < s_.resources.size(); ++k)
            if (s_.resources[k].name == name) return static_cast<int>(k);
          return -1;
        }();
        else use.index = -1;
        if (use.index >= 0) {
          const auto& list = use.target == PassUse::Target::input    ? s_.inputs
                             : use.target == PassUse::Target::output ? s_.outputs
                                                                     : s_.resources;
          port = &list[use.index];
        }
        if (!port) {
          d_.error(usage.pos(), up, "'" + target + "' names no in.PORT, out.PORT or tmp.RESOURCE");
        } else if (!component.empty()) {
          const auto& components = port->type.components();
          for (size_t c = 0; c < components.size(); ++c)
            if (components[c].name == component) use.component = static_cast<int>(c);
          if (use.component < 0) d_.error(usage.pos(), up, "'" + port->type.name() + "' has no component '" + component + "'");
        }
        auto u = usage.is_string() ? parse_usage(usage.as_string()) : std::nullopt;
        if (!u) d_.error(usage.pos(), up, "unknown usage");
        else use.usage = *u;
        spec.uses.push_back(use);
      }
    }
    s_.passes.push_back(std::move(spec));
  }

  // A bypass's or a requirement's "when": {"scene_lacks": FEATURE} or {"param": NAME, "equals" or
  // "at_most": VALUE}, either with "unless_linked": an input's name or a list of them.
  Condition condition(const JsonValue& when, const std::string& wp) {
    Condition c;
    if (const JsonValue* lacks = when.find("scene_lacks")) {
      auto f = lacks->is_string() ? parse_scene_feature(lacks->as_string()) : std::nullopt;
      if (!f) d_.error(lacks->pos(), wp, "unknown scene feature");
      else c = {Condition::Kind::scene_lacks, *f, -1, {}, {}};
    } else if (const JsonValue* param = when.find("param")) {
      c.param = param->is_string() ? s_.find_param(param->as_string()) : -1;
      if (c.param < 0) d_.error(param->pos(), wp, "no such param");
      if (const JsonValue* eq = when.find("equals")) c = {Condition::Kind::param_equals, SceneFeature::count, c.param, *eq, {}};
      else if (const JsonValue* le = when.find("at_most")) c = {Condition::Kind::param_at_most, SceneFeature::count, c.param, *le, {}};
      else d_.error(when.pos(), wp, "expected \"equals\" or \"at_most\"");
    } else {
      d_.error(when.pos(), wp, "expected {\"scene_lacks\": FEATURE} or {\"param\": NAME, \"equals\"|\"at_most\": VALUE}");
    }
    if (const JsonValue* unless = when.find("unless_linked")) {
      for (const JsonValue& name : one_or_many(*unless)) {
        const int input = name.is_string() ? s_.find_input(name.as_string()) : -1;
        if (input < 0) d_.error(name.pos(), wp, "\"unless_linked\" names no input");
        else c.unless_linked.push_back(input);
      }
    }
    return c;
  }

  static std::span<const JsonValue> one_or_many(const JsonValue& v) {
    return v.is_array() ? std::span<const JsonValue>(v.items()) : std::span<const JsonValue>(&v, 1);
  }

  // {"when": CONDITION (optional), "scene_has": FEATURE (optional), "linked": [INPUT or [INPUT, ...],
  // ...], "reason": TEXT}: each entry of "linked" must be fed, a list by any one of its inputs.
  void requirement(const JsonValue& v, const std::string& p) {
    check_keys(v, p, {"when", "scene_has", "linked", "reason"});
    LinkRequirement req;
    if (const JsonValue* when = v.find("when")) {
      if (!when->is_object()) d_.error(when->pos(), json_pointer_append(p, "when"), "expected an object");
      else req.when = condition(*when, json_pointer_append(p, "when"));
    }
    if (const JsonValue* has = v.find("scene_has")) {
      req.scene_has = has->is_string() ? parse_scene_feature(has->as_string()) : std::nullopt;
      if (!req.scene_has) d_.error(has->pos(), json_pointer_append(p, "scene_has"), "unknown scene feature");
    }
    const JsonValue* linked = v.find("linked");
    const std::string lp = json_pointer_append(p, "linked");
    if (!linked || !linked->is_array() || linked->items().empty()) {
      d_.error(linked ? linked->pos() : v.pos(), lp, "expected a list of input names (a list in it: any one of them)");
    } else {
      for (const JsonValue& group : linked->items()) {
        std::vector<int>& inputs = req.linked.emplace_back();
        for (const JsonValue& name : one_or_many(group)) {
          const int input = name.is_string() ? s_.find_input(name.as_string()) : -1;
          if (input < 0) d_.error(name.pos(), lp, "names no input");
          else inputs.push_back(input);
        }
      }
    }
    req.reason = string_at(v, p, "reason", true);
    s_.requires_linked.push_back(std::move(req));
  }

  void bypass(const JsonValue& v, const std::string& p) {
    check_keys(v, p, {"when", "forward", "reason"});
    BypassRule rule;
    const JsonValue* when = v.find("when");
    if (!when || !when->is_object()) d_.error(v.pos(), p, "missing \"when\"");
    else rule.when = condition(*when, json_pointer_append(p, "when"));
    const JsonValue* forward = v.find("forward");
    if (forward && forward->is_object()) {
      for (const auto& [out, in] : forward->members()) {
        int o = s_.find_output(out), i = in.is_string() ? s_.find_input(in.as_string()) : -1;
        if (o < 0 || (i < 0 && !in.is_null()))
          d_.error(in.pos(), json_pointer_append(p, "forward"), "forward maps an output name to an input name or null");
        else rule.forward.emplace_back(o, i);
      }
    }
    if (rule.forward.size() != s_.outputs.size())
      d_.error(v.pos(), p, "a bypass must forward every output from an input");
    rule.reason = string_at(v, p, "reason", false);
    if (rule.reason.empty() && rule.when.kind == Condition::Kind::scene_lacks) rule.reason = scene_lacks_reason(rule.when.feature);
    if (rule.reason.empty()) d_.error(v.pos(), p, "missing \"reason\"");
    s_.bypass.push_back(std::move(rule));
  }
};

}  // namespace

std::optional<NodeSchema> read_node_schema(std::string_view json_text, Diagnostics& diagnostics) {
  auto root = read_json(json_text, diagnostics);
  if (!root) return std::nullopt;
  size_t before = diagnostics.error_count();
  NodeSchema schema;
  schema.file = diagnostics.file();
  SchemaReader(schema, diagnostics).read(*root);
  if (diagnostics.error_count() > before) return std::nullopt;
  return schema;
}

}  // namespace lg
