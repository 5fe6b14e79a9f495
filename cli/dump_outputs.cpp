#include "cli/dump_outputs.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "graph/json_writer.h"
#include "nodes/raytrace/vti_file.h"
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

// A 3D texture as VTK image data, one file a mip (NAME.vti, NAME.mip1.vti, ...) that
// vtkXMLImageDataReader and ParaView open: texel (i, j, k) at point (i, j, k) of level 0's
// texels, a coarser mip's points at the centres of the level-0 blocks they cover, so that every
// mip lies over the others.
void dump_volume(Executor& executor, const PlanResource& r, const fs::path& dir) {
  const LoweredResource& d = r.desc;
  for (uint32_t mip = 0; mip < d.mips; ++mip) {
    const std::vector<float> rgba = executor.read_image(d.name, {mip, 0});
    VtiImage image;
    image.comment = "dumped by lumagraph render: " + d.name + " (" + std::string(d.format) + "), mip " +
                    std::to_string(mip) + " of " + std::to_string(d.mips) + "; rgba as the node's port doc says";
    image.dims = {std::max(d.width >> mip, 1u), std::max(d.height >> mip, 1u), std::max(d.layers >> mip, 1u)};
    const double block = double(1u << mip);
    image.spacing = glm::dvec3(block);
    image.origin = glm::dvec3((block - 1.0) / 2.0);
    image.arrays.push_back({"rgba", 4, rgba});
    image.scalars = "rgba";
    const std::string name = d.name + (mip > 0 ? ".mip" + std::to_string(mip) : "") + ".vti";
    std::string error;
    if (!write_file_atomically((dir / name).string(), encode_vti(image), &error)) throw std::runtime_error(error);
  }
}

void dump_image(Executor& executor, const PlanResource& r, const fs::path& dir) {
  static const char* faces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  const LoweredResource& d = r.desc;
  const uint32_t layers = d.layers;  // 2D textures and cube maps (3D ones: dump_volume)
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
      save_image((dir / (name + ".exr")).string(), w, h, rgba);
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
    else if (r.desc.kind == ResourceKind::texture3d)
      dump_volume(executor, r, dir);
    else
      dump_image(executor, r, dir);
    ++files;
  }
  std::printf("dumped %zu node outputs to %s\n", files, dir.c_str());
}

}  // namespace lg::cli
