// glTF 2.0 import (see mesh_import.h). tinygltf parses the JSON, buffers and images; every index
// and byte range it leaves unchecked is checked here before it is read.
#include <tiny_gltf.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <map>
#include <string_view>
#include <utility>

#include "runtime/scene/contained_path.h"
#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_tangents.h"
#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/scene_error.h"

namespace lg {
namespace {

// What is wrong inside the file; import_gltf() adds the file's name.
struct Malformed {
  std::string message;
};

[[noreturn]] void fail(std::string message) {
  throw Malformed{std::move(message)};
}

template <class T>
const T& item(const std::vector<T>& items, int index, const std::string& what) {
  if (index < 0 || static_cast<size_t>(index) >= items.size())
    fail(what + " " + std::to_string(index) + " does not exist (the file has " + std::to_string(items.size()) + ")");
  return items[static_cast<size_t>(index)];
}

// An accessor's elements, checked to lie inside its buffer view and buffer.
struct ElementRange {
  const unsigned char* data = nullptr;
  size_t stride = 0, count = 0;
  int component_type = 0, components = 0;
  bool normalized = false;

  double component(size_t element, int c) const {
    const unsigned char* p = data + element * stride;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalize(p[c], 255.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalize(v, 65535.0);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      default:
        fail("unsupported component type " + std::to_string(component_type));
    }
  }
  double normalize(double v, double max) const { return normalized ? v / max : v; }
};

ElementRange elements(const tinygltf::Model& model, int index, const std::string& what, int type,
                      std::initializer_list<int> component_types) {
  const auto& a = item(model.accessors, index, what + ": accessor");
  std::string name = what + " (accessor " + std::to_string(index) + ")";
  if (a.sparse.isSparse) fail(name + " is sparse, which is not supported");
  if (a.type != type) fail(name + " has the wrong type");
  bool type_ok = false;
  for (int t : component_types) type_ok |= a.componentType == t;
  if (!type_ok) fail(name + " has an unsupported component type " + std::to_string(a.componentType));
  const auto& view = item(model.bufferViews, a.bufferView, name + ": buffer view");
  const auto& buffer = item(model.buffers, view.buffer, name + ": buffer");
  size_t element_size = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(a.componentType)) *
                        static_cast<size_t>(tinygltf::GetNumComponentsInType(a.type));
  size_t stride = view.byteStride ? view.byteStride : element_size;
  if (stride < element_size) fail(name + ": the byte stride is smaller than an element");
  if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
    fail(name + ": buffer view " + std::to_string(a.bufferView) + " runs past the end of buffer " +
         std::to_string(view.buffer) + " (" + std::to_string(buffer.data.size()) + " bytes)");
  // Written so that no product can overflow: count is bounded by the view's length first.
  bool fits = a.byteOffset <= view.byteLength && a.count <= view.byteLength &&
              (a.count == 0 || (a.count - 1) * stride + element_size <= view.byteLength - a.byteOffset);
  if (!fits)
    fail(name + ": " + std::to_string(a.count) + " elements run past the end of buffer view " +
         std::to_string(a.bufferView));
  return {buffer.data.data() + view.byteOffset + a.byteOffset,
          stride,
          a.count,
          a.componentType,
          tinygltf::GetNumComponentsInType(a.type),
          a.normalized};
}

glm::vec3 vec3_or(const std::vector<double>& v, glm::vec3 fallback) {
  return v.size() == 3 ? glm::vec3(v[0], v[1], v[2]) : fallback;
}

class GltfImporter {
 public:
  GltfImporter(World& world, const tinygltf::Model& model, std::string stem)
      : world_(world), model_(model), stem_(std::move(stem)) {}

  std::vector<Entity> run(Entity parent) {
    check_extensions();
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      roots = item(model_.scenes, scene, "scene").nodes;
    } else {
      std::vector<bool> is_child(model_.nodes.size(), false);
      for (const auto& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[static_cast<size_t>(c)] = true;
      for (size_t i = 0; i < model_.nodes.size(); ++i)
        if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    std::vector<Entity> made;
    for (int node : roots) made.push_back(add_node(node, parent));
    return made;
  }

  // What the file uses that was left out, each once, in the order found.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  // A required extension the importer cannot read is an error; an optional one is a warning.
  void check_extensions() {
    static constexpr std::string_view supported[] = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                     "KHR_texture_transform"};
    auto is_supported = [&](const std::string& name) {
      return std::find(std::begin(supported), std::end(supported), name) != std::end(supported);
    };
    for (const auto& name : model_.extensionsRequired)
      if (!is_supported(name))
        fail("the file requires the extension " + name +
             ", which is not supported (supported: KHR_lights_punctual, KHR_materials_emissive_strength, "
             "KHR_texture_transform)");
    for (const auto& name : model_.extensionsUsed)
      if (!is_supported(name)) warn("the extension " + name + " is not supported and was ignored");
  }

  Entity add_node(int index, Entity parent) {
    const auto& node = item(model_.nodes, index, "node");
    if (std::find(path_.begin(), path_.end(), index) != path_.end())
      fail("node " + std::to_string(index) + " is its own ancestor");
    if (path_.size() > 256) fail("the node hierarchy is deeper than 256");
    path_.push_back(index);
    Entity e = world_.create(node.name.empty() ? stem_ + " node " + std::to_string(index) : node.name);
    world_.add<Transform>(e, node_transform(node, index, parent));
    if (node.mesh >= 0) add_mesh(node.mesh, e);
    if (node.camera >= 0) add_camera(node.camera, e);
    add_light(node, e);
    for (int child : node.children) add_node(child, e);
    path_.pop_back();
    return e;
  }

  Transform node_transform(const tinygltf::Node& node, int index, Entity parent) {
    Transform t;
    t.parent = parent;
    std::string name = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(name + ": a matrix needs 16 numbers");
      float values[16];
      for (int k = 0; k < 16; ++k) values[k] = static_cast<float>(node.matrix[static_cast<size_t>(k)]);
      glm::vec3 skew;
      glm::vec4 perspective;
      if (!glm::decompose(glm::make_mat4(values), t.scale, t.rotation, t.position, skew, perspective))
        fail(name + ": the matrix is not a translation, rotation and scale");
      return t;
    }
    if (!node.translation.empty() && node.translation.size() != 3) fail(name + ": a translation needs 3 numbers");
    if (!node.scale.empty() && node.scale.size() != 3) fail(name + ": a scale needs 3 numbers");
    if (!node.rotation.empty() && node.rotation.size() != 4) fail(name + ": a rotation needs 4 numbers");
    t.position = vec3_or(node.translation, glm::vec3(0.0f));
    t.scale = vec3_or(node.scale, glm::vec3(1.0f));
    if (node.rotation.size() == 4) {  // glTF stores x, y, z, w
      glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]));
      float length = glm::length(q);
      if (!(length > 0.0f) || !std::isfinite(length)) fail(name + ": the rotation is not a unit quaternion");
      t.rotation = q / length;
    }
    return t;
  }

  void add_mesh(int index, Entity node_entity) {
    const auto& mesh = item(model_.meshes, index, "mesh");
    if (!meshes_.count(index)) {
      auto& primitives = meshes_[index];
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (mesh.primitives[p].mode != TINYGLTF_MODE_TRIANGLES) continue;
        const int m = material(mesh.primitives[p].material);
        MeshData data = read_primitive(mesh, index, p);
        // A normal map needs tangents; those of the file come first.
        if (m >= 0 && data.tangents.empty()) {
          const TextureRef& normal_map = world_.materials()[static_cast<size_t>(m)].normal_texture;
          if (normal_map.texture >= 0) generate_tangents(data, normal_map.texcoord);
        }
        primitives.push_back({world_.add_mesh(std::move(data)), m});
      }
    }
    const auto& primitives = meshes_[index];
    for (size_t p = 0; p < primitives.size(); ++p) {
      // The node's own entity draws the first primitive; children draw the others.
      Entity e = node_entity;
      if (p > 0) {
        e = world_.create(mesh.name + " primitive " + std::to_string(p));
        world_.add<Transform>(e, {glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f), node_entity});
      }
      world_.add<MeshRenderer>(e, primitives[p]);
    }
  }

  MeshData read_primitive(const tinygltf::Mesh& mesh, int index, size_t p) {
    const auto& prim = mesh.primitives[p];
    std::string what = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
    MeshData out;
    out.name = (mesh.name.empty() ? stem_ + " mesh " + std::to_string(index) : mesh.name) +
               (mesh.primitives.size() > 1 ? "/" + std::to_string(p) : "");
    auto attribute = [&](const char* key) {
      auto found = prim.attributes.find(key);
      return found == prim.attributes.end() ? -1 : found->second;
    };
    if (attribute("POSITION") < 0) fail(what + " has no POSITION");
    ElementRange positions = elements(model_, attribute("POSITION"), what + " POSITION", TINYGLTF_TYPE_VEC3,
                                      {TINYGLTF_COMPONENT_TYPE_FLOAT});
    for (size_t i = 0; i < positions.count; ++i)
      out.positions.emplace_back(positions.component(i, 0), positions.component(i, 1), positions.component(i, 2));
    if (attribute("NORMAL") >= 0) {
      ElementRange n =
          elements(model_, attribute("NORMAL"), what + " NORMAL", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
      if (n.count != positions.count) fail(what + ": NORMAL and POSITION counts differ");
      for (size_t i = 0; i < n.count; ++i) {
        glm::vec3 v(n.component(i, 0), n.component(i, 1), n.component(i, 2));
        float length = glm::length(v);
        out.normals.push_back(length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f, 1.0f, 0.0f));
      }
    }
    read_uvs(attribute("TEXCOORD_0"), what + " TEXCOORD_0", positions.count, out.uvs);
    read_uvs(attribute("TEXCOORD_1"), what + " TEXCOORD_1", positions.count, out.uvs1);
    if (attribute("COLOR_0") >= 0) {
      const int type = item(model_.accessors, attribute("COLOR_0"), what + " COLOR_0: accessor").type;
      ElementRange c = elements(model_, attribute("COLOR_0"), what + " COLOR_0",
                                type == TINYGLTF_TYPE_VEC3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4, unit_types);
      if (c.count != positions.count) fail(what + ": COLOR_0 and POSITION counts differ");
      for (size_t i = 0; i < c.count; ++i)
        out.colors.emplace_back(c.component(i, 0), c.component(i, 1), c.component(i, 2),
                                c.components == 4 ? c.component(i, 3) : 1.0);
    }
    if (attribute("TANGENT") >= 0) {
      ElementRange t = elements(model_, attribute("TANGENT"), what + " TANGENT", TINYGLTF_TYPE_VEC4,
                                {TINYGLTF_COMPONENT_TYPE_FLOAT});
      if (t.count != positions.count) fail(what + ": TANGENT and POSITION counts differ");
      for (size_t i = 0; i < t.count; ++i) {
        glm::vec3 v(t.component(i, 0), t.component(i, 1), t.component(i, 2));
        float length = glm::length(v);
        if (!(length > 0.0f) || !std::isfinite(length))
          fail(what + ": TANGENT " + std::to_string(i) + " is not a direction");
        out.tangents.emplace_back(v / length, t.component(i, 3) < 0.0 ? -1.0f : 1.0f);
      }
    }
    if (prim.indices >= 0) {
      ElementRange ix = elements(model_, prim.indices, what + " indices", TINYGLTF_TYPE_SCALAR,
                                 {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
      ix.normalized = false;
      for (size_t i = 0; i < ix.count; ++i) out.indices.push_back(static_cast<uint32_t>(ix.component(i, 0)));
    } else {
      for (size_t i = 0; i < positions.count; ++i) out.indices.push_back(static_cast<uint32_t>(i));
    }
    out.indices.resize(out.indices.size() - out.indices.size() % 3);  // a trailing partial triangle is dropped
    if (std::string problem = mesh_problem(out); !problem.empty()) fail(what + ": " + problem);
    if (out.normals.empty()) generate_normals(out);
    return out;
  }

  // Float or normalised unsigned integers, as glTF allows for uvs and colours.
  static constexpr std::initializer_list<int> unit_types = {
      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

  void read_uvs(int accessor, const std::string& what, size_t count, std::vector<glm::vec2>& out) {
    if (accessor < 0) return;
    ElementRange uv = elements(model_, accessor, what, TINYGLTF_TYPE_VEC2, unit_types);
    if (uv.count != count) fail(what + " and POSITION counts differ");
    for (size_t i = 0; i < uv.count; ++i) out.emplace_back(uv.component(i, 0), uv.component(i, 1));
  }

  int material(int index) {
    if (index < 0) return -1;
    if (auto found = materials_.find(index); found != materials_.end()) return found->second;
    const auto& m = item(model_.materials, index, "material");
    const auto& pbr = m.pbrMetallicRoughness;
    PbrMaterial out;
    out.name = m.name.empty() ? stem_ + " material " + std::to_string(index) : m.name;
    if (pbr.baseColorFactor.size() == 4)
      out.base_color =
          glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    out.roughness = std::clamp(static_cast<float>(pbr.roughnessFactor), 0.0f, 1.0f);
    out.metalness = std::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
    out.emissive = vec3_or(m.emissiveFactor, glm::vec3(0.0f));
    if (auto strength = m.extensions.find("KHR_materials_emissive_strength"); strength != m.extensions.end()) {
      const auto& value = strength->second.Get("emissiveStrength");
      if (value.IsNumber() && value.GetNumberAsDouble() >= 0.0)
        out.emissive *= static_cast<float>(value.GetNumberAsDouble());
      else if (value.Type() != tinygltf::NULL_TYPE)
        fail(out.name + ": emissiveStrength is not a number of 0 or more");
    }
    std::string where = "material " + std::to_string(index) + " ('" + out.name + "')";
    out.base_color_texture = texture_ref(pbr.baseColorTexture, ColorSpace::srgb, where + " baseColorTexture");
    out.metallic_roughness_texture =
        texture_ref(pbr.metallicRoughnessTexture, ColorSpace::linear, where + " metallicRoughnessTexture");
    out.normal_texture = texture_ref(m.normalTexture, ColorSpace::linear, where + " normalTexture");
    out.normal_scale = static_cast<float>(m.normalTexture.scale);
    out.occlusion_texture = texture_ref(m.occlusionTexture, ColorSpace::linear, where + " occlusionTexture");
    out.occlusion_strength = std::clamp(static_cast<float>(m.occlusionTexture.strength), 0.0f, 1.0f);
    out.emissive_texture = texture_ref(m.emissiveTexture, ColorSpace::srgb, where + " emissiveTexture");
    if (m.alphaMode == "MASK")
      out.alpha_mode = AlphaMode::mask;
    else if (m.alphaMode == "BLEND")
      out.alpha_mode = AlphaMode::blend;
    else if (m.alphaMode != "OPAQUE")
      fail(where + ": alphaMode '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND");
    out.alpha_cutoff = static_cast<float>(m.alphaCutoff);
    if (!(out.alpha_cutoff >= 0.0f)) fail(where + ": alphaCutoff " + std::to_string(m.alphaCutoff) + " is below 0");
    out.double_sided = m.doubleSided;
    return materials_[index] = world_.add_material(std::move(out));
  }

  // A material's texture: TextureInfo, NormalTextureInfo or OcclusionTextureInfo, with
  // KHR_texture_transform. `what` names it in errors and warnings.
  template <class Info>
  TextureRef texture_ref(const Info& info, ColorSpace color_space, const std::string& what) {
    TextureRef out;
    if (info.index < 0) return out;
    out.texture = texture(info.index, color_space);
    out.sampling = sampling(item(model_.textures, info.index, what + ": texture").sampler, what);
    out.texcoord = info.texCoord;
    if (auto ext = info.extensions.find("KHR_texture_transform"); ext != info.extensions.end()) {
      const tinygltf::Value& t = ext->second;
      auto pair = [&](const char* key, glm::vec2 fallback) {
        if (!t.Has(key)) return fallback;
        const auto& v = t.Get(key);
        if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
          fail(what + ": KHR_texture_transform " + key + " needs 2 numbers");
        return glm::vec2(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
      };
      out.offset = pair("offset", out.offset);
      out.scale = pair("scale", out.scale);
      if (t.Has("rotation")) {
        if (!t.Get("rotation").IsNumber()) fail(what + ": KHR_texture_transform rotation is not a number");
        out.rotation = static_cast<float>(t.Get("rotation").GetNumberAsDouble());
      }
      if (t.Has("texCoord")) {
        if (!t.Get("texCoord").IsInt()) fail(what + ": KHR_texture_transform texCoord is not an integer");
        out.texcoord = t.Get("texCoord").GetNumberAsInt();
      }
    }
    if (out.texcoord != 0 && out.texcoord != 1) {
      warn(what + " uses TEXCOORD_" + std::to_string(out.texcoord) + "; only sets 0 and 1 are read, set 0 is used");
      out.texcoord = 0;
    }
    return out;
  }

  TextureSampling sampling(int index, const std::string& what) {
    TextureSampling out;
    if (index < 0) return out;  // glTF: repeat, and filtering left to the renderer
    const auto& s = item(model_.samplers, index, what + ": sampler");
    auto wrap = [&](int mode, const char* axis) {
      switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT:
          return TextureWrap::repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
          return TextureWrap::clamp_to_edge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
          return TextureWrap::mirrored_repeat;
      }
      fail(what + ": sampler " + std::to_string(index) + " has an unknown " + axis + " " + std::to_string(mode));
    };
    out.wrap_u = wrap(s.wrapS, "wrapS");
    out.wrap_v = wrap(s.wrapT, "wrapT");
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.mag = TextureFilter::nearest;
    switch (s.minFilter) {
      case TINYGLTF_TEXTURE_FILTER_NEAREST:
        out.min = TextureFilter::nearest, out.mip = MipFilter::none;
        break;
      case TINYGLTF_TEXTURE_FILTER_LINEAR:
        out.mip = MipFilter::none;
        break;
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
        out.min = TextureFilter::nearest, out.mip = MipFilter::nearest;
        break;
      case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
        out.mip = MipFilter::nearest;
        break;
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
        out.min = TextureFilter::nearest;
        break;
      default:  // LINEAR_MIPMAP_LINEAR, or not given
        break;
    }
    return out;
  }

  void warn(const std::string& message) {
    if (std::find(warnings_.begin(), warnings_.end(), message) == warnings_.end()) warnings_.push_back(message);
  }

  // Every image is decoded once per colour space it is used in (an image may serve as colour
  // and data at once, though rarely).
  int texture(int index, ColorSpace color_space) {
    const auto& t = item(model_.textures, index, "texture");
    const std::pair key(t.source, color_space);
    if (auto found = images_.find(key); found != images_.end()) return found->second;
    const auto& image = item(model_.images, t.source, "texture " + std::to_string(index) + ": image");
    std::string what =
        "image " + std::to_string(t.source) + (image.uri.empty() ? "" : " ('" + image.uri.substr(0, 64) + "')");
    if (image.image.empty() || image.width <= 0 || image.height <= 0) fail(what + " could not be loaded");
    int channels = image.component, bytes = image.bits / 8;
    size_t texels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    if (channels < 1 || channels > 4 || (bytes != 1 && bytes != 2) ||
        image.image.size() != texels * static_cast<size_t>(channels * bytes))
      fail(what + " has an unsupported layout");
    TextureData out;
    out.name = image.name.empty() ? what : image.name;
    out.width = static_cast<uint32_t>(image.width);
    out.height = static_cast<uint32_t>(image.height);
    out.color_space = color_space;
    out.rgba8.resize(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
      // 16-bit values are little-endian: the high byte is the second.
      auto channel = [&](int c) {
        return image.image[(i * static_cast<size_t>(channels) + static_cast<size_t>(c)) * static_cast<size_t>(bytes) +
                           static_cast<size_t>(bytes - 1)];
      };
      bool gray = channels < 3;
      for (int c = 0; c < 3; ++c) out.rgba8[i * 4 + static_cast<size_t>(c)] = channel(gray ? 0 : c);
      out.rgba8[i * 4 + 3] = channels == 2 ? channel(1) : channels == 4 ? channel(3) : 255;
    }
    return images_[key] = world_.add_texture(std::move(out));
  }

  void add_camera(int index, Entity e) {
    const auto& c = item(model_.cameras, index, "camera");
    if (c.type != "perspective") return;
    Camera camera;
    if (c.perspective.yfov > 0.0 && c.perspective.yfov < 3.1)
      camera.vertical_fov = static_cast<float>(c.perspective.yfov);
    if (c.perspective.znear > 0.0) camera.near_plane = static_cast<float>(c.perspective.znear);
    world_.add<Camera>(e, camera);
  }

  // The spec's bounds: 0 <= innerConeAngle < outerConeAngle <= pi/2.
  static SpotLight spot_light(const tinygltf::Light& light, int index, glm::vec3 color, float intensity) {
    const double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= glm::half_pi<double>()))
      fail("light " + std::to_string(index) + " (a spot) has cone angles inner " + std::to_string(inner) + ", outer " +
           std::to_string(outer) + "; expected 0 <= innerConeAngle < outerConeAngle <= pi/2");
    SpotLight spot;
    spot.color = color;
    spot.intensity = intensity;
    spot.range = static_cast<float>(light.range);
    spot.inner_cone_angle = static_cast<float>(inner);
    spot.outer_cone_angle = static_cast<float>(outer);
    return spot;
  }

  void add_light(const tinygltf::Node& node, Entity e) {
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.Has("light")) return;
    const auto& ref = ext->second.Get("light");
    if (!ref.IsNumber() && !ref.IsInt()) fail("a KHR_lights_punctual light reference is not a number");
    const auto& light = item(model_.lights, ref.GetNumberAsInt(), "light");
    glm::vec3 color = vec3_or(light.color, glm::vec3(1.0f));
    auto intensity = static_cast<float>(light.intensity);
    if (light.type == "directional")
      world_.add<DirectionalLight>(e, {color, intensity, 0.00465f, true});
    else if (light.type == "point")
      world_.add<PointLight>(e, {color, intensity, static_cast<float>(light.range)});
    else if (light.type == "spot")
      world_.add<SpotLight>(e, spot_light(light, ref.GetNumberAsInt(), color, intensity));
  }

  World& world_;
  const tinygltf::Model& model_;
  std::string stem_;
  std::vector<int> path_;  // the nodes from the root to the one being added
  std::map<int, std::vector<MeshRenderer>> meshes_;
  std::map<int, int> materials_;
  std::map<std::pair<int, ColorSpace>, int> images_;
  std::vector<std::string> warnings_;  // each once, in the order found
};

// tinygltf reads the files a glTF file refers to through this (contained_path.h says why).
// Only regular files: a folder (a uri that is empty once its NUL bytes end it, found by fuzzing)
// has tinygltf size a buffer of 2^63 bytes, which throws std::bad_alloc past every catch.
bool contained_read(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* folder) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path.c_str(), ec)) {
    if (error) *error += "'" + std::string(path.c_str()) + "' is not a file";
    return false;
  }
  if (inside_folder(path, *static_cast<std::string*>(folder)))
    return tinygltf::ReadWholeFile(out, error, path, nullptr);
  if (error) *error += "'" + path + "' is outside the folder of the glTF file";
  return false;
}

std::string unexpanded(const std::string& path, void*) {
  return path;
}

bool no_writes(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error += "writing is not allowed";
  return false;
}

}  // namespace

std::vector<Entity> import_gltf(World& world, const std::string& path, Entity parent) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  std::string ext = std::filesystem::path(path).extension().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path, "the file does not exist");
  std::string folder = folder_of(path);
  // Existence is not checked against the folder, so that reading is tried and refused by name.
  loader.SetFsCallbacks({tinygltf::FileExists, unexpanded, contained_read, no_writes, &folder});
  bool ok = ext == ".glb" || ext == ".GLB" ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                           : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  if (!ok) {
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    // A uri's NUL bytes reach the message inside paths; written out, so the message goes on.
    for (size_t at = error.find('\0'); at != std::string::npos; at = error.find('\0', at))
      error.replace(at, 1, "\\u0000");
    throw SceneError(path, "not a valid glTF file: " + (error.empty() ? std::string("unknown error") : error));
  }
  try {
    GltfImporter importer(world, model, std::filesystem::path(path).stem().string());
    std::vector<Entity> made = importer.run(parent);
    for (const auto& w : importer.warnings()) world.warnings.push_back(path + ": " + w);
    return made;
  } catch (const Malformed& m) {
    throw SceneError(path, m.message);
  }
}

}  // namespace lg
