#include "graph/port_type.h"

#include <map>

namespace lg {
namespace {

struct KindInfo {
  ResourceKind resource;
  std::string words;                                                       // how error messages name the kind
  std::map<std::string, std::vector<PortComponent>, std::less<>> classes;  // "" when classless
};

const std::map<std::string, KindInfo, std::less<>>& kinds() {
  static const std::map<std::string, KindInfo, std::less<>> table = {
      {"texture2d",
       {ResourceKind::texture2d,
        "a 2D texture",
        {{"hdr", {{"", "rgba16f", 8}}},
         {"ldr", {{"", "rgba8", 4}}},  // sRGB-encoded by the writer: storage images cannot be sRGB
         {"mask", {{"", "r8", 1}}},
         {"vector", {{"", "rgba8_snorm", 4}}},
         {"float", {{"", "r32f", 4}}},
         {"depth", {{"", "d32f", 4, true}}},
         {"motion", {{"", "rg16f", 4}}},
         {"lut", {{"", "rg16f", 4}}}}}},
      {"cube", {ResourceKind::cube, "a cube map", {{"hdr", {{"", "rgba16f", 8}}}}}},
      {"texture3d",
       {ResourceKind::texture3d,
        "a 3D texture",
        {{"hdr", {{"", "rgba16f", 8}}}, {"sh", {{"", "rgba16f", 8}}}, {"mask", {{"", "r8", 1}}}}}},
      {"sh", {ResourceKind::buffer, "a spherical-harmonics buffer", {{"", {{"", "buffer", 16}}}}}},
      {"scalar", {ResourceKind::buffer, "a scalar", {{"", {{"", "buffer", 4}}}}}},
      // gi.irradiance_volume's probe volumes: the block of 64 volumes of 160 bytes its lookup
      // reads (nodes/gi/irradiance_volume/probe_atlas.h, GpuProbeVolume x kMaxProbeVolumes); the
      // atlas images stay with the producing kernel (PassContext::producer).
      {"probe_volume", {ResourceKind::buffer, "a probe volume", {{"", {{"", "buffer", 64 * 160}}}}}},
      {"gbuffer",
       {ResourceKind::texture2d,
        "a G-buffer",
        {{"",
          {{"depth", "d32f", 4, true},
           {"normal", "rgb10a2", 4},
           {"albedo", "rgba8_srgb", 4},
           {"material", "rg8", 2},
           {"motion", "rg16f", 4},
           {"emissive", "rgba16f", 8}}}}}},
  };
  return table;
}

}  // namespace

std::optional<PortType> parse_port_type(std::string_view text, bool allow_wildcard, std::string* error) {
  size_t colon = text.find(':');
  std::string_view kind = text.substr(0, colon);
  std::string_view cls = colon == std::string_view::npos ? "" : text.substr(colon + 1);
  auto it = kinds().find(kind);
  if (it == kinds().end()) {
    if (error) *error = "unknown port kind '" + std::string(kind) + "'";
    return std::nullopt;
  }
  static const std::vector<PortComponent> none;  // wildcards have no layout of their own
  const KindInfo& info = it->second;
  if (cls == "*" && allow_wildcard && !info.classes.contains(""))
    return PortType{std::string(kind), "*", info.resource, &none};
  auto layout = info.classes.find(cls);
  if (layout == info.classes.end()) {
    if (error) {
      *error = "'" + std::string(kind) + "' has no format class '" + std::string(cls) + "'; expected one of";
      for (const auto& [name, _] : info.classes)
        *error += " '" + std::string(kind) + (name.empty() ? "" : ":" + name) + "'";
    }
    return std::nullopt;
  }
  return PortType{std::string(kind), std::string(cls), info.resource, &layout->second};
}

bool port_types_compatible(const PortType& from, const PortType& to, std::string* why) {
  if (from.layout && from.layout == to.layout) return true;  // one entry of the table: same kind and class
  if (from.kind != to.kind) {
    if (why) *why = kinds().at(from.kind).words + " cannot feed " + kinds().at(to.kind).words;
    return false;
  }
  if (to.is_wildcard() || from.format_class == to.format_class) return true;
  if (why) *why = "the formats differ: " + from.name() + " is not " + to.name();
  return false;
}

std::vector<PortType> all_port_types() {
  std::vector<PortType> out;
  for (const auto& [kind, info] : kinds())
    for (const auto& [cls, layout] : info.classes) out.push_back({kind, cls, info.resource, &layout});
  return out;
}

}  // namespace lg
