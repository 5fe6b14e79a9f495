// Writes small seed files for the binary formats that neither examples/ nor the tests keep on
// disk: occlusion bakes of every mode and PRT bakes of every transfer (whole and a chunk), a
// probe bake of two volumes (whole and a chunk), a reference part file and an EXR environment.
// scripts/fuzz runs it into the seed corpora; usage: lumagraph-fuzz-seeds OUT_DIR (one folder
// per harness is made in it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "nodes/gi/path_tracer/reference_file.h"
#include "nodes/gi/probes/probe_file.h"
#include "nodes/gi/prt/prt_file.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/raytrace/ray_scene.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/mesh_generators.h"

namespace fs = std::filesystem;

namespace lg {
namespace {

// A floor with a box on it.
SceneView small_scene() {
  SceneView view;
  const std::pair<MeshData, glm::mat4> placed[] = {
      {make_quad(4.0f, 4.0f), glm::mat4(1.0f)},
      {make_box(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), {0.5f, 0.5f, 0.0f})}};
  for (const auto& [mesh, world] : placed) {
    DrawItem draw;
    draw.mesh = int(view.meshes.size());
    draw.world = world;
    view.meshes.push_back(std::make_shared<const MeshData>(mesh));
    view.draws.push_back(draw);
  }
  return view;
}

void write_bakes(const fs::path& dir) {
  const SceneView view = small_scene();
  const WorldMesh mesh = make_world_mesh(view);
  const RayScene scene(mesh, view);
  const OcclusionSettings settings{.rays = 4};
  const BakeDomain domains[] = {BakeDomain::vertices(mesh), BakeDomain::lightmap(mesh, 16),
                                BakeDomain::volume(mesh, {3, 0, 0})};
  for (const BakeDomain& domain : domains)
    for (uint32_t count : {1u, 2u}) {
      BakeFile file;
      file.header = make_bake_header(domain, mesh, "small.json", settings, 7, 0, count);
      if (domain.mode() == BakeMode::texel) file.lightmap_uvs = domain.lightmap_uvs();
      file.data = run_bake(scene, domain, settings, 7, file.header.range);
      write_bake_file(
          (dir / (std::string(bake_mode_name(domain.mode())) + "-" + std::to_string(count) + ".lgbake")).string(),
          file);
    }
}

// PRT bakes of the same scene (the bake harness reads them too): each transfer kind, whole
// and a chunk.
void write_prt_bakes(const fs::path& dir) {
  const PathScene scene(small_scene(), PathEnvironment::none());
  for (TransferKind kind : {TransferKind::unshadowed, TransferKind::shadowed, TransferKind::interreflected}) {
    const PrtSettings settings{
        .kind = kind, .order = 2, .rays = 4, .bounces = kind == TransferKind::interreflected ? 1u : 0u};
    for (uint32_t count : {1u, 2u}) {
      PrtFile file;
      file.header = make_prt_header(scene.surfaces().mesh(), "small.json", settings, 0, count);
      file.data = bake_transfer(scene, settings, file.header.range);
      write_prt_file((dir / (std::string(transfer_kind_name(kind)) + "-" + std::to_string(count) + ".lgprt")).string(),
                     file);
    }
  }
}

void write_probes(const fs::path& dir) {
  IrradianceVolumeData a, b;
  a.size = {2.0f, 1.0f, 3.0f}, a.probe_counts = {2, 2, 2};
  b.world = glm::rotate(glm::translate(glm::mat4(1.0f), {1.0f, 2.0f, -3.0f}), 0.7f, glm::vec3(0.0f, 1.0f, 0.0f));
  b.size = {1.5f, 0.5f, 1.0f}, b.probe_counts = {2, 1, 1};
  for (uint32_t count : {1u, 2u}) {
    ProbeFile file;
    file.header = make_probe_header({a, b}, 0, count);
    file.header.scene = "rooms.json", file.header.graph = "<default>";
    file.header.settings = {.rays = 16, .bounces = 1, .seed = 3};
    file.probes.resize(file.header.range.size());
    for (size_t i = 0; i < file.probes.size(); ++i) {
      file.probes[i].active = i % 3 != 0;
      file.probes[i].offset = glm::vec3(0.01f * float(i));
    }
    write_probe_file((dir / ("two-volumes-" + std::to_string(count) + ".lgprobes")).string(), file);
  }
}

void write_reference_parts(const fs::path& dir) {
  for (uint32_t count : {1u, 2u}) {
    ReferencePart part;
    part.run = "scene=a spp=4", part.chunk_index = 0, part.chunk_count = count;
    ReferenceImage& image = part.image;
    image.width = 3, image.height = 2;
    chunk_rows(image.height, 0, count, image.row_begin, image.row_end);
    for (size_t a = 0; a < kReferenceAovCount; ++a)
      for (size_t i = 0; i < image.pixel_count(); ++i) {
        image.mean[a].push_back(glm::vec3(float(a + i) + 0.5f));
        image.standard_error[a].push_back(glm::vec3(0.25f));
      }
    write_reference_part((dir / ("part-0-of-" + std::to_string(count))).string(), part);
  }
}

void write_environments(const fs::path& dir) {
  const uint32_t width = 8, height = 4;
  std::vector<float> rgba;
  for (uint32_t i = 0; i < width * height; ++i)
    rgba.insert(rgba.end(), {float(i), 0.5f, std::exp2(float(i) - 8.0f), 1.0f});
  save_image((dir / "ramp.exr").string(), width, height, rgba, {.compress = false, .full_float = true});
  save_image((dir / "ramp-zip.exr").string(), width, height, rgba);
  save_image((dir / "ramp.hdr").string(), width, height, rgba);
  for (float& v : rgba) v = std::min(v / 8.0f, 1.0f);  // PNG holds [0, 1]
  save_image((dir / "ramp.png").string(), width, height, rgba);
}

}  // namespace
}  // namespace lg

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 1;
  }
  const fs::path out = argv[1];
  const std::pair<const char*, void (*)(const fs::path&)> writers[] = {{"bake", lg::write_bakes},
                                                                       {"bake", lg::write_prt_bakes},
                                                                       {"probes", lg::write_probes},
                                                                       {"reference_part", lg::write_reference_parts},
                                                                       {"env_image", lg::write_environments}};
  for (const auto& [name, write] : writers) {
    fs::create_directories(out / name);
    write(out / name);
  }
  return 0;
}
