// Wavefront OBJ import (see mesh_import.h). obj_syntax.h checks the text strictly (the MTL
// libraries' too), tinyobjloader then parses it, and vertices are shared between faces that use
// the same position, normal and uv.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "runtime/scene/contained_path.h"
#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/obj_syntax.h"
#include "runtime/scene/scene_error.h"

namespace lg {
namespace {

PbrMaterial pbr_from_mtl(const tinyobj::material_t& m) {
  PbrMaterial out;
  out.name = m.name;
  out.base_color = glm::vec4(m.diffuse[0], m.diffuse[1], m.diffuse[2], std::clamp(m.dissolve, 0.0f, 1.0f));
  out.roughness = roughness_from_specular_exponent(m.shininess);
  out.metalness = std::clamp(m.metallic, 0.0f, 1.0f);
  out.emissive = glm::vec3(m.emission[0], m.emission[1], m.emission[2]);
  return out;
}

// One mesh being built from the faces of one object that share a material.
struct MeshBuilder {
  MeshData mesh;
  std::map<std::tuple<int, int, int>, uint32_t> vertices;  // (position, normal, uv) -> vertex
  bool every_corner_has_normal = true, every_corner_has_uv = true;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "the file cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Reads the MTL libraries tinyobjloader asks for: from the OBJ file's folder or below only, each
// checked by obj_syntax.h before it is parsed. The OBJ check already refuses libraries outside
// the folder at their line, but tinyobjloader splits `mtllib` lines its own way (spaces only,
// with escapes), so the names it asks for are checked here again. tinyobjloader only warns when
// a library fails, so the problems wait in `problems` for import_obj to throw; a missing
// library leaves the default material, as many OBJ files ship without theirs.
class ContainedMtlReader final : public tinyobj::MaterialReader {
 public:
  explicit ContainedMtlReader(const std::string& obj_path) : folder_(folder_of(obj_path)), problems_(obj_path) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warning, std::string* error) override {
    const std::string path = folder_ + "/" + name;
    if (!inside_folder(path, folder_)) {
      problems_.error({}, "", "the material library '" + name + "' is outside the OBJ file's folder");
      return false;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    std::string text = read_text(path);
    if (Diagnostics mtl = check_mtl_text(path, text); mtl.has_errors()) {
      for (const Diagnostic& d : mtl.items()) problems_.add(d);
      return false;
    }
    std::istringstream stream(std::move(text));
    tinyobj::LoadMtl(names, materials, &stream, warning, error);
    return true;
  }

  const Diagnostics& problems() const { return problems_; }

 private:
  std::string folder_;
  Diagnostics problems_;
};

// obj_syntax.h has checked every index; this guards the arrays should tinyobjloader ever
// resolve one differently.
void check_index(const std::string& path, int index, size_t count, const char* what, const std::string& shape) {
  if (index < 0 || static_cast<size_t>(index) >= count)
    throw SceneError(
        path, "object '" + shape + "' uses " + what + " " + std::to_string(index + 1) + " of " + std::to_string(count));
}

}  // namespace

float roughness_from_specular_exponent(float ns) {
  float alpha = std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f));
  return std::clamp(std::sqrt(alpha), 0.0f, 1.0f);
}

std::vector<Entity> import_obj(World& world, const std::string& path, Entity parent) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path, "the file does not exist");
  std::string text = read_text(path);
  if (Diagnostics problems = check_obj_text(path, text); problems.has_errors()) throw SceneError(std::move(problems));
  // The text checked is the text parsed (the file is read once).
  std::istringstream stream(std::move(text));
  ContainedMtlReader mtl_reader(path);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> mtl_materials;
  std::string warning, error;
  if (!tinyobj::LoadObj(&attrib, &shapes, &mtl_materials, &warning, &error, &stream, &mtl_reader, /*triangulate=*/true,
                        /*default_vcols_fallback=*/false)) {
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    throw SceneError(path, "not a valid OBJ file: " + (error.empty() ? std::string("unknown error") : error));
  }
  if (mtl_reader.problems().has_errors()) throw SceneError(mtl_reader.problems());
  size_t position_count = attrib.vertices.size() / 3, normal_count = attrib.normals.size() / 3,
         uv_count = attrib.texcoords.size() / 2;
  std::vector<int> materials;
  for (const auto& m : mtl_materials) materials.push_back(world.add_material(pbr_from_mtl(m)));
  std::string stem = std::filesystem::path(path).stem().string();

  std::vector<Entity> made;
  for (const auto& shape : shapes) {
    std::string shape_name = shape.name.empty() ? stem : shape.name;
    std::map<int, MeshBuilder> by_material;
    size_t corner = 0;
    for (size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      size_t corners = shape.mesh.num_face_vertices[face];
      int material = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
      if (material >= static_cast<int>(materials.size())) material = -1;
      if (corners != 3) {  // tinyobjloader triangulates; anything else is left out
        corner += corners;
        continue;
      }
      MeshBuilder& b = by_material[material];
      for (size_t k = 0; k < 3; ++k, ++corner) {
        if (corner >= shape.mesh.indices.size()) throw SceneError(path, "object '" + shape_name + "' is truncated");
        const auto& ix = shape.mesh.indices[corner];
        check_index(path, ix.vertex_index, position_count, "vertex", shape_name);
        if (ix.normal_index >= 0) check_index(path, ix.normal_index, normal_count, "normal", shape_name);
        if (ix.texcoord_index >= 0) check_index(path, ix.texcoord_index, uv_count, "texture coordinate", shape_name);
        b.every_corner_has_normal &= ix.normal_index >= 0;
        b.every_corner_has_uv &= ix.texcoord_index >= 0;
        auto key = std::tuple(ix.vertex_index, ix.normal_index, ix.texcoord_index);
        auto [found, added] = b.vertices.emplace(key, static_cast<uint32_t>(b.mesh.positions.size()));
        if (added) {
          auto p = static_cast<size_t>(ix.vertex_index) * 3;
          b.mesh.positions.emplace_back(attrib.vertices[p], attrib.vertices[p + 1], attrib.vertices[p + 2]);
          auto n = static_cast<size_t>(std::max(ix.normal_index, 0)) * 3;
          b.mesh.normals.push_back(ix.normal_index >= 0
                                       ? glm::vec3(attrib.normals[n], attrib.normals[n + 1], attrib.normals[n + 2])
                                       : glm::vec3(0.0f));
          auto t = static_cast<size_t>(std::max(ix.texcoord_index, 0)) * 2;
          b.mesh.uvs.push_back(ix.texcoord_index >= 0 ? glm::vec2(attrib.texcoords[t], 1.0f - attrib.texcoords[t + 1])
                                                      : glm::vec2(0.0f));
        }
        b.mesh.indices.push_back(found->second);
      }
    }
    for (auto& [material, b] : by_material) {
      b.mesh.name =
          shape_name +
          (by_material.size() > 1 && material >= 0 ? "/" + mtl_materials[static_cast<size_t>(material)].name : "");
      if (!b.every_corner_has_uv) b.mesh.uvs.clear();
      if (std::string problem = mesh_problem(b.mesh); !problem.empty())
        throw SceneError(path, "object '" + shape_name + "': " + problem);
      if (b.every_corner_has_normal) {
        for (auto& n : b.mesh.normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
      } else {
        generate_normals(b.mesh);
      }
      Entity e = world.create(b.mesh.name);
      world.add<Transform>(e, {glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f), parent});
      world.add<MeshRenderer>(
          e, {world.add_mesh(std::move(b.mesh)), material >= 0 ? materials[static_cast<size_t>(material)] : -1});
      made.push_back(e);
    }
  }
  if (made.empty()) throw SceneError(path, "the file has no triangles");
  return made;
}

}  // namespace lg
