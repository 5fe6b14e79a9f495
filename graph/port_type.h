// Port types: what flows along a link. A type is a resource kind plus a format class, written
// "texture2d:hdr", "cube:hdr", "sh", "gbuffer". Outputs have one concrete type; an input may
// accept any class of a kind ("texture2d:*"). The table here also gives each type its physical
// layout (formats and bytes per texel), which lowering uses to size resources.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lg {

enum class ResourceKind : uint8_t { texture2d, cube, texture3d, buffer };

// One physical image or buffer of a port type (a G-buffer has several).
struct PortComponent {
  std::string name;         // "" for single-resource types
  std::string format;       // "rgba16f", "r8", "d32f", ... or "buffer"
  uint32_t bytes_per_texel;  // for buffers: bytes per element
  bool depth = false;       // a depth format: attached as depth, not as colour
};

struct PortType {
  std::string kind;          // "texture2d", "cube", "texture3d", "sh", "gbuffer", "scalar"
  std::string format_class;  // "hdr", "ldr", "mask", ... or "*" (inputs only); empty if none
  // Looked up once by parse_port_type, as lowering asks for them at every port.
  ResourceKind resource = ResourceKind::texture2d;
  // Into port_type.cpp's table, which lives as long as the program: plans may keep views of
  // its strings.
  const std::vector<PortComponent>* layout = nullptr;  // empty for wildcards

  const std::vector<PortComponent>& components() const { return *layout; }

  std::string name() const { return format_class.empty() ? kind : kind + ':' + format_class; }
  bool is_wildcard() const { return format_class == "*"; }
  friend bool operator==(const PortType&, const PortType&) = default;
};

// Parses "texture2d:hdr"; nullopt with `error` set when the kind or class is unknown.
std::optional<PortType> parse_port_type(std::string_view text, bool allow_wildcard,
                                        std::string* error);

// Whether an output of type `from` may feed an input of type `to`; when not, `why` says so in
// words a user understands.
bool port_types_compatible(const PortType& from, const PortType& to, std::string* why);

// All known concrete port types, for `lumagraph nodes` and the editor's port colours.
std::vector<PortType> all_port_types();

}  // namespace lg
