// read_occlusion_bake(): a vertex or texel bake turned into per-mesh MeshOcclusion, after checking
// that it belongs to the meshes.
#include "nodes/occlusion/baked/occlusion_bake_reader.h"

#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {
namespace {

// The meshes as the bake traced them: each drawn once with its transform (identity for
// `lumagraph bake MODEL`, whose lone model's draws sit at the origin).
WorldMesh baked_geometry(std::span<const MeshData* const> meshes, std::span<const glm::mat4> transforms) {
  SceneView view;
  for (size_t m = 0; m < meshes.size(); ++m) {
    view.draws.push_back({.mesh = int(view.meshes.size()), .world = transforms[m]});
    view.meshes.emplace_back(std::shared_ptr<void>(), meshes[m]);  // aliased: the caller keeps them
  }
  return make_world_mesh(view);
}

// Bake space to mesh space for bent normals: the inverse of the normal matrix.
glm::mat3 to_mesh_space(const glm::mat4& world) {
  return glm::transpose(glm::mat3(world));
}

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string describe_parts(const std::vector<WorldMesh::Part>& parts) {
  std::string out = std::to_string(parts.size()) + (parts.size() == 1 ? " mesh" : " meshes") + " (";
  for (size_t p = 0; p < parts.size(); ++p)
    out += (p ? ", " : "") + ("'" + parts[p].name + "' " + std::to_string(parts[p].vertex_count) + " vertices");
  return out + ")";
}

// A vertex's bake in mesh space; one with nothing baked (no normal) reads as open: k_A 1, the
// mesh's normal as the bent normal.
glm::vec4 vertex_value(const BakeData& data, size_t point, glm::vec3 mesh_normal, const glm::mat3& to_mesh) {
  if (!(data.valid[point] > 0.0f)) return glm::vec4(mesh_normal, 1.0f);
  const glm::vec3 bent = to_mesh * glm::vec3(data.bent_normal[3 * point], data.bent_normal[3 * point + 1],
                                             data.bent_normal[3 * point + 2]);
  const float length = glm::length(bent);
  return glm::vec4(length > 0.0f ? bent / length : mesh_normal, data.visibility[point]);
}

}  // namespace

std::vector<std::shared_ptr<const MeshOcclusion>> read_occlusion_bake(const std::string& bake_path,
                                                                      std::span<const MeshData* const> meshes,
                                                                      std::span<const glm::mat4> transforms) {
  const BakeFile file = read_bake_file(bake_path);  // BakeFileError names the file
  const BakeHeader& h = file.header;
  const std::string bake = "the bake '" + bake_path + "'";
  if (h.mode == BakeMode::volume)
    throw std::runtime_error(bake +
                             " is a volume bake, which belongs to a whole scene rather than to a mesh; bake "
                             "per vertex or per texel for a mesh, or use the occlusion.bake node, which bakes a "
                             "volume of the scene itself");
  if (h.chunk_count != 1)
    throw std::runtime_error(bake + " is chunk " + std::to_string(h.chunk_index) + " of " +
                             std::to_string(h.chunk_count) + "; merge the chunks first (lumagraph bake merge)");
  if (transforms.size() != meshes.size()) throw std::invalid_argument("read_occlusion_bake: a transform per mesh");
  const WorldMesh geometry = baked_geometry(meshes, transforms);
  const std::string made_from = " was made from '" + h.input + "'";
  if (h.mode == BakeMode::vertex) {
    bool same = h.parts.size() == geometry.parts.size();
    for (size_t p = 0; same && p < h.parts.size(); ++p)
      same = h.parts[p].vertex_count == geometry.parts[p].vertex_count;
    if (!same)
      throw std::runtime_error(bake + made_from + ", " + describe_parts(h.parts) + ", but this draws " +
                               describe_parts(geometry.parts) +
                               "; bake this model alone, with no transform, or the scene file itself");
  } else if (h.triangles != geometry.triangle_count()) {
    throw std::runtime_error(bake + made_from + " with " + std::to_string(h.triangles) + " triangles, but this has " +
                             std::to_string(geometry.triangle_count()) +
                             "; bake this model alone, with no transform, or the scene file itself");
  }
  if (const uint64_t hash = world_mesh_hash(geometry); hash != h.input_hash)
    throw std::runtime_error(bake + made_from + ", whose geometry hash " + hex(h.input_hash) +
                             " differs from this one's " + hex(hash) +
                             " (the same counts, other positions or normals: bake again)");

  std::vector<std::shared_ptr<const MeshOcclusion>> out;
  if (h.mode == BakeMode::vertex) {
    for (size_t p = 0; p < geometry.parts.size(); ++p) {
      const WorldMesh::Part& part = geometry.parts[p];
      auto m = std::make_shared<MeshOcclusion>();
      m->kind = MeshOcclusion::Kind::vertex;
      m->source = bake_path;
      for (uint32_t v = 0; v < part.vertex_count; ++v)
        m->vertices.push_back(
            vertex_value(file.data, part.first_vertex + v, meshes[p]->normals[v], to_mesh_space(transforms[p])));
      out.push_back(std::move(m));
    }
    return out;
  }
  auto lightmap = std::make_shared<OcclusionLightmap>();
  lightmap->size = h.lightmap_size;
  lightmap->texels.resize(file.data.size());
  for (size_t t = 0; t < file.data.size(); ++t)
    lightmap->texels[t] = {file.data.bent_normal[3 * t], file.data.bent_normal[3 * t + 1],
                           file.data.bent_normal[3 * t + 2], file.data.visibility[t]};
  size_t corner = 0;  // lightmap_uvs: 2 floats a corner, every triangle of every mesh in order
  for (size_t p = 0; p < meshes.size(); ++p) {
    const MeshData* mesh = meshes[p];
    auto m = std::make_shared<MeshOcclusion>();
    m->kind = MeshOcclusion::Kind::texel;
    m->source = bake_path;
    m->lightmap = lightmap;
    m->lightmap_to_mesh = to_mesh_space(transforms[p]);
    for (size_t c = 0; c < mesh->indices.size(); ++c, ++corner)
      m->lightmap_uvs.emplace_back(file.lightmap_uvs[2 * corner], file.lightmap_uvs[2 * corner + 1]);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace lg
