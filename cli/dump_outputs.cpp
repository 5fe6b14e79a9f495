#include "cli/dump_outputs.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "graph/json_writer.h"
#include "runtime/exec/executor.h"
#include "runtime/image/image_file.h"

namespace lg::cli {
namespace {

namespace fs = std::filesystem;

// Ports are "node.port" (bundles "node.port.component"); internal resources ("node/name") and
// previous-frame copies ("X@previous") are not ports.
bool is_port(const std::string& name) {
  return name.find('/') == std::string::npos && name.find('@') == std::string::npos;
}

void dump_image(Executor& executor, const PlanResource& r, const fs::path& dir) {
  static const char* faces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  const LoweredResource& d = r.desc;
  const uint32_t layers = d.kind == ResourceKind::texture2d || d.kind == ResourceKind::cube ? d.layers : 1;
  for (uint32_t mip = 0; mip < d.mips; ++mip)
    for (uint32_t layer = 0; layer < layers; ++layer) {
      std::string name = d.name;
      if (d.kind == ResourceKind::cube)
        name += std::string(".") + faces[layer % 6];
      else if (layers > 1)
        name += ".layer" + std::to_string(layer);
      if (mip > 0) name += ".mip" + std::to_string(mip);
      std::vector<float> rgba = executor.read_image(d.name, {mip, layer});
      const uint32_t w = std::max(d.width >> mip, 1u), h = std::max(d.height >> mip, 1u);
      const uint32_t depth = d.kind == ResourceKind::texture3d ? std::max(d.layers >> mip, 1u) : 1;
      save_image((dir / (name + ".exr")).string(), w, h * depth, rgba);  // 3D: slices stacked
    }
}

// Buffers hold 32-bit floats: an SH buffer one RGB(A) vec4 per coefficient, a scalar one float.
void dump_buffer(Executor& executor, const PlanResource& r, const fs::path& dir) {
  std::vector<std::byte> bytes = executor.read_buffer(r.desc.name);
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
  JsonValue doc = JsonValue::object();
  doc.set("resource", r.desc.name);
  JsonValue items = JsonValue::array();
  const bool vec4 = r.desc.format == "buffer" && r.desc.bytes % 16 == 0 && r.desc.bytes > 4;
  if (vec4) {
    doc.set("layout", "one [r, g, b, w] per real SH coefficient, index l (l + 1) + m, orthonormal, no Condon-Shortley phase, +Z polar; coefficient 0's w counts non-finite texels (docs/env-conventions.md)");
    for (size_t i = 0; i + 3 < values.size(); i += 4) {
      JsonValue v = JsonValue::array();
      for (int c = 0; c < 4; ++c) v.push(double(values[i + c]));
      items.push(std::move(v));
    }
  } else {
    for (float v : values) items.push(double(v));
  }
  doc.set("values", std::move(items));
  std::string error;
  const fs::path file = dir / (r.desc.name + ".json");
  if (!write_file_atomically(file.string(), write_json(doc), &error)) throw std::runtime_error(error);
}

}  // namespace

void dump_outputs(Executor& executor, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the dump folder: " + ec.message());
  size_t files = 0;
  for (const PlanResource& r : executor.plan().resources) {
    if (!is_port(r.desc.name) || r.placement.block < 0) continue;
    if (r.desc.kind == ResourceKind::buffer)
      dump_buffer(executor, r, dir);
    else
      dump_image(executor, r, dir);
    ++files;
  }
  std::printf("dumped %zu node outputs to %s\n", files, dir.c_str());
}

}  // namespace lg::cli
