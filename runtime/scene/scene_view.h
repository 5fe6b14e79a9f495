// The world as one frame's passes see it: the camera, every drawable mesh with its material and
// transform, and every light, flattened out of the ECS world (runtime/scene/world.h) by
// make_scene_view(). Kernels read only this, never the world, so a host engine may also fill it
// itself. Units: metres; light colours are linear RGB (Rec.709 primaries).
//
// Meshes and textures are shared, not copied: make_scene_view() hands out the World's own
// assets behind shared_ptr<const>, so a frame's view costs a pointer per asset, and a view stays
// valid after the world changes or goes (World::edit_mesh() copies an asset a view still holds
// before changing it). `version` says when their contents changed; kernels re-upload or re-bake
// on that, never by comparing pointers. A host engine filling the view itself either makes its
// own (std::make_shared<const MeshData>(...)) or points at meshes it keeps alive for as long as
// the view is used, through shared_ptr's aliasing constructor:
// std::shared_ptr<const MeshData>(std::shared_ptr<void>(), &its_mesh).
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "graph/scene_summary.h"
#include "runtime/scene/components.h"
#include "runtime/scene/mesh_occlusion.h"

namespace lg {

// Triangles in the mesh's own space; counter-clockwise seen from outside.
struct MeshData {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // one per position, unit length
  std::vector<glm::vec2> uvs;       // empty, or one per position (texcoord set 0)
  std::vector<glm::vec2> uvs1;      // texcoord set 1: empty, or one per position
  std::vector<glm::vec4> colors;    // linear RGBA multiplying the base colour: empty, or one per position
  std::vector<glm::vec4> tangents;  // xyz unit, w = +-1 the bitangent's sign: empty, or one per position
  std::vector<uint32_t> indices;    // three per triangle
  std::shared_ptr<const MeshOcclusion> occlusion;  // baked offline, or null (mesh_occlusion.h)
};

// How a texture's bytes are to be read: colour (base colour, emissive) is sRGB-encoded, data
// (normals, metallic-roughness, occlusion) is linear.
enum class ColorSpace : uint8_t { srgb, linear };

// An RGBA8 texture as decoded from a file, rows top to bottom. The GPU builds its mip chain.
struct TextureData {
  std::string name;
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba8;
  ColorSpace color_space = ColorSpace::srgb;
};

enum class TextureWrap : uint8_t { repeat, clamp_to_edge, mirrored_repeat };
enum class TextureFilter : uint8_t { nearest, linear };
enum class MipFilter : uint8_t { none, nearest, linear };  // none: mip 0 only

// glTF's sampler: wrap per axis, magnification, minification and the filter between mips.
struct TextureSampling {
  TextureWrap wrap_u = TextureWrap::repeat, wrap_v = TextureWrap::repeat;
  TextureFilter mag = TextureFilter::linear, min = TextureFilter::linear;
  MipFilter mip = MipFilter::linear;
  friend bool operator==(const TextureSampling&, const TextureSampling&) = default;
};

// One texture as a material uses it: which texcoord set, KHR_texture_transform (uv' =
// T(offset) R(rotation) S(scale) uv, rotation counter-clockwise in radians) and the sampler.
struct TextureRef {
  int texture = -1;  // index into SceneView::textures, or -1: none
  int texcoord = 0;  // 0: MeshData::uvs, 1: MeshData::uvs1
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;
  TextureSampling sampling{};
};

enum class AlphaMode : uint8_t { opaque, mask, blend };

// glTF 2.0 metallic-roughness.
struct PbrMaterial {
  std::string name;
  glm::vec4 base_color{1.0f};  // linear; multiplies the texture and the vertex colours
  float roughness = 0.5f;      // perceptual roughness (alpha = roughness^2); multiplies the texture's G
  float metalness = 0.0f;      // multiplies the metallic-roughness texture's B
  glm::vec3 emissive{0.0f};  // radiance, linear RGB (KHR_materials_emissive_strength folded in); multiplies the texture
  TextureRef base_color_texture{};          // sRGB
  TextureRef metallic_roughness_texture{};  // linear: G roughness, B metalness
  TextureRef normal_texture{};              // linear, tangent space
  float normal_scale = 1.0f;                // scales the normal texture's x and y
  TextureRef occlusion_texture{};           // linear: R is the ambient (IBL) occlusion
  float occlusion_strength = 1.0f;          // occlusion = 1 + strength * (R - 1)
  TextureRef emissive_texture{};            // sRGB
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;  // MASK: alpha below it is not drawn
  bool double_sided = false;  // both sides drawn, the back with its normal flipped
};

struct DrawItem {
  int mesh = -1;      // index into SceneView::meshes
  int material = -1;  // index into SceneView::materials; -1: the default PbrMaterial
  glm::mat4 world{1.0f};
  glm::mat4 previous_world{1.0f};  // last frame's, for motion vectors
  uint64_t entity = 0;             // Entity::id() of its world entity: matches draws across frames
  bool captured_by_probes = true;  // MeshRenderer::captured_by_probes
};

// Vulkan clip space with reversed Z: depth 1 at the near plane, 0 at infinity (infinite far
// plane), y down in clip space as Vulkan has it.
struct CameraView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 previous_view_projection{1.0f};
  glm::vec3 position{0.0f};
  float vertical_fov = 1.0f;  // radians
  float near_plane = 0.05f;
  float aperture = 0.0f;  // lens diameter in metres; 0 is a pinhole
  float focus_distance = 5.0f;
  // Sub-pixel offset of this frame's projection in normalized device coordinates, for temporal
  // anti-aliasing (camera_jitter.h): clip.xy += jitter * clip.w. Unset, the executor jitters
  // the camera with the Halton sequence when the plan asks for it (a graph with post.taa) and
  // leaves it still otherwise; set (a reference, a host with its own sequence), it is used as is.
  // `projection` and `previous_view_projection` never contain it.
  std::optional<glm::vec2> jitter;
};

struct DirectionalLightData {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, the way the light travels
  glm::vec3 irradiance{1.0f};              // on a surface facing the light, W/m^2 per channel
  float angular_radius = 0.00465f;         // radians (the sun's)
  bool casts_shadows = true;
};

struct PointLightData {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};  // W/sr per channel
  float range = 0.0f;         // 0: no cut-off
  bool casts_shadows = true;
};

// A point light within a cone: the glTF spot's angular falloff (deferred README) times the
// point light's range window and inverse square.
struct SpotLightData {
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, the cone's axis, the way the light travels
  glm::vec3 intensity{1.0f};               // W/sr per channel, on the axis
  float range = 0.0f;                      // 0: no cut-off
  float inner_cone_angle = 0.0f;           // radians from the axis
  float outer_cone_angle = 0.7853982f;     // radians from the axis, at most pi/2
  bool casts_shadows = true;
};

// Uniform Lambertian emitters; `radiance` is W/(m^2 sr) per channel (see
// nodes/lighting/deferred/README.md for the formulas).
struct SphereLightData {
  glm::vec3 center{0.0f};
  float radius = 0.1f;
  glm::vec3 radiance{1.0f};
  bool casts_shadows = true;
};

struct TubeLightData {  // a capsule around the segment end0-end1
  glm::vec3 end0{0.0f}, end1{1.0f, 0.0f, 0.0f};
  float radius = 0.05f;
  glm::vec3 radiance{1.0f};
  bool casts_shadows = true;
};

struct RectLightData {  // one-sided lights emit toward cross(half_x, half_y)
  glm::vec3 center{0.0f};
  glm::vec3 half_x{0.5f, 0.0f, 0.0f}, half_y{0.0f, 0.5f, 0.0f};
  glm::vec3 radiance{1.0f};
  bool two_sided = false;
  bool casts_shadows = true;
};

// A box of probes on a regular grid, centred on its entity (the IrradianceVolume component).
struct IrradianceVolumeData {
  glm::mat4 world{1.0f};  // the entity's frame
  glm::vec3 size{1.0f};   // of the box, in that frame
  glm::ivec3 probe_counts{4};
  uint64_t entity = 0;  // Entity::id()
};

// A reflection probe (the ReflectionProbe component) in its entity's frame.
struct ReflectionProbeData {
  glm::mat4 world{1.0f};  // the entity's frame: the cube is taken at its origin
  ReflectionProbe probe;
  uint64_t entity = 0;  // Entity::id()
};

struct EnvironmentData {
  std::string path;        // an HDR/EXR file; empty: the procedural sky of the graph
  float intensity = 1.0f;  // multiplies the environment's radiance
};

struct SceneView {
  std::string name;
  uint64_t version = 0;  // changes whenever meshes, materials or textures change (GPU re-upload)
  CameraView camera;
  std::vector<std::shared_ptr<const MeshData>> meshes;  // never null where a draw uses it
  std::vector<std::shared_ptr<const TextureData>> textures;
  std::vector<PbrMaterial> materials;
  std::vector<DrawItem> draws;
  std::vector<DirectionalLightData> directional_lights;
  std::vector<PointLightData> point_lights;
  std::vector<SpotLightData> spot_lights;
  std::vector<SphereLightData> sphere_lights;
  std::vector<TubeLightData> tube_lights;
  std::vector<RectLightData> rect_lights;
  bool has_environment = false;
  EnvironmentData environment;
  std::vector<IrradianceVolumeData> irradiance_volumes;
  std::vector<ReflectionProbeData> reflection_probes;
  // The planes the planar reflectors lie in (MeshRenderer::reflector_plane in the world), each
  // once: xyz the unit normal they face, w: n . p + w = 0.
  std::vector<glm::vec4> planar_reflectors;
  float exposure = 0.0f;  // EV from the world's PostProcessSettings
  // Frame timing for temporal nodes (post.exposure's adaptation): seconds since the previous
  // frame, and a camera cut (history no longer describes this view: temporal state restarts).
  // lg::Renderer::render's FrameTiming sets them; make_scene_view leaves 1/60 s and no cut.
  float frame_seconds = 1.0f / 60.0f;
  bool camera_cut = false;

  // The draw's material, or the default PbrMaterial when it has none (material -1, which the ECS
  // uses for "default") or an index out of range.
  const PbrMaterial& material_of(const DrawItem& draw) const;
  // The draw's mesh; throws std::invalid_argument when its index is out of range or its slot null.
  const MeshData& mesh_of(const DrawItem& draw) const;

  // What the compiler specializes on: counts of each light kind, probes, reflector planes, glossy materials
  // (any drawn with roughness below 0.9 or any metal; a draw without a material counts as the
  // default PbrMaterial), whether any drawn mesh carries baked occlusion, the camera's aperture
  // and focus.
  SceneSummary summary() const;
};

}  // namespace lg
