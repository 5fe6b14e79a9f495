// glTF import of the metal-rough material model from the assets of scripts/make-test-gltf
// (examples/gltf/): every material field, texture colour spaces, samplers, texcoord sets,
// KHR_texture_transform, KHR_materials_emissive_strength, vertex colours, tangents read or
// generated, and how unsupported extensions are reported. Tolerance on imported numbers: 1e-5
// (floats from JSON doubles); on 8-bit normalised values 1e-6 (the division is exact in float).
#include <gtest/gtest.h>

#include <filesystem>

#include "import_test_support.h"
#include "runtime/scene/mesh_import.h"

namespace lg {
namespace {

using test::error_of;
using test::read_bytes;
using test::replaced;
using test::write_variant;

std::string asset(const std::string& name) {
  return (std::filesystem::path(LUMAGRAPH_SOURCE_DIR "/examples/gltf") / name).string();
}

World load(const std::string& path) {
  World w;
  import_gltf(w, path);
  return w;
}

const TextureData& texture_of(const World& w, const TextureRef& ref) {
  EXPECT_GE(ref.texture, 0);
  return *w.textures().at(static_cast<size_t>(ref.texture));
}

TEST(GltfMaterialImport, NormalTextureAndGeneratedTangents) {
  World w = load(asset("normal-mapped-plane.gltf"));
  ASSERT_EQ(w.materials().size(), 1u);
  const PbrMaterial& m = w.materials()[0];
  EXPECT_EQ(m.normal_scale, 1.0f);
  EXPECT_EQ(texture_of(w, m.normal_texture).color_space, ColorSpace::linear);
  EXPECT_EQ(m.normal_texture.texcoord, 0);
  EXPECT_EQ(m.base_color_texture.texture, -1);
  ASSERT_EQ(w.meshes().size(), 1u);
  const MeshData& mesh = *w.meshes()[0];
  ASSERT_EQ(mesh.tangents.size(), 4u);  // the file has none: generated for the normal map
  for (const auto& t : mesh.tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
  EXPECT_TRUE(w.warnings.empty());
}

TEST(GltfMaterialImport, MaskDoubleSidedAndSampler) {
  World w = load(asset("cut-out-quad.gltf"));
  ASSERT_EQ(w.materials().size(), 2u);
  const PbrMaterial& leaf = w.materials()[0];
  EXPECT_EQ(leaf.alpha_mode, AlphaMode::mask);
  EXPECT_NEAR(leaf.alpha_cutoff, 0.5f, 1e-5f);
  EXPECT_TRUE(leaf.double_sided);
  EXPECT_EQ(texture_of(w, leaf.base_color_texture).color_space, ColorSpace::srgb);
  const TextureSampling& s = leaf.base_color_texture.sampling;
  EXPECT_EQ(s.wrap_u, TextureWrap::clamp_to_edge);
  EXPECT_EQ(s.wrap_v, TextureWrap::clamp_to_edge);
  EXPECT_EQ(s.mag, TextureFilter::nearest);
  EXPECT_EQ(s.min, TextureFilter::nearest);
  EXPECT_EQ(s.mip, MipFilter::none);  // minFilter NEAREST: no mipmapping
  const TextureData& t = texture_of(w, leaf.base_color_texture);
  ASSERT_EQ(t.rgba8.size(), 4u * 4u * 4u);
  EXPECT_EQ(t.rgba8[3], 255);                  // texel (0, 0) opaque
  EXPECT_EQ(t.rgba8[(1 * 4 + 1) * 4 + 3], 0);  // texel (1, 1) transparent
  const PbrMaterial& wall = w.materials()[1];
  EXPECT_EQ(wall.alpha_mode, AlphaMode::opaque);
  EXPECT_FALSE(wall.double_sided);
}

TEST(GltfMaterialImport, AlphaModeBlendAndBadModes) {
  std::string text = read_bytes(asset("cut-out-quad.gltf"));
  World w = load(write_variant("blend.gltf", replaced(text, "\"MASK\"", "\"BLEND\"")));
  EXPECT_EQ(w.materials()[0].alpha_mode, AlphaMode::blend);
  std::string path = write_variant("bad-alpha-mode.gltf", replaced(text, "\"MASK\"", "\"CUTOUT\""));
  std::string error = error_of([&] { load(path); });
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("alphaMode 'CUTOUT' is not OPAQUE, MASK or BLEND"), std::string::npos) << error;
}

TEST(GltfMaterialImport, EmissiveTextureFactorAndStrength) {
  World w = load(asset("emissive-surface.gltf"));
  const PbrMaterial& m = w.materials()[0];
  EXPECT_NEAR(m.emissive.r, 4.0f, 1e-5f);  // factor (1, 0.5, 0.25) x strength 4
  EXPECT_NEAR(m.emissive.g, 2.0f, 1e-5f);
  EXPECT_NEAR(m.emissive.b, 1.0f, 1e-5f);
  EXPECT_EQ(texture_of(w, m.emissive_texture).color_space, ColorSpace::srgb);
  EXPECT_TRUE(w.warnings.empty());
}

TEST(GltfMaterialImport, MetallicRoughnessOcclusionTexcoordSetsAndTransform) {
  World w = load(asset("metal-rough-plane.gltf"));
  const PbrMaterial& m = w.materials()[0];
  EXPECT_EQ(m.metalness, 1.0f);
  EXPECT_EQ(m.roughness, 1.0f);
  // One image used twice as data: decoded once, linear.
  EXPECT_EQ(m.metallic_roughness_texture.texture, m.occlusion_texture.texture);
  EXPECT_EQ(w.textures().size(), 1u);
  EXPECT_EQ(texture_of(w, m.occlusion_texture).color_space, ColorSpace::linear);
  EXPECT_EQ(m.occlusion_strength, 1.0f);
  for (const TextureRef* ref : {&m.metallic_roughness_texture, &m.occlusion_texture}) {
    EXPECT_EQ(ref->texcoord, 1);
    EXPECT_EQ(ref->offset, glm::vec2(1, 0));
    EXPECT_EQ(ref->scale, glm::vec2(-1, 1));
    EXPECT_EQ(ref->rotation, 0.0f);
  }
  const MeshData& mesh = *w.meshes()[0];
  ASSERT_EQ(mesh.uvs1.size(), 4u);
  EXPECT_EQ(mesh.uvs1[0], glm::vec2(1, 1));
  ASSERT_EQ(mesh.colors.size(), 4u);
  EXPECT_NEAR(mesh.colors[0].r, 128.0f / 255.0f, 1e-6f);
  EXPECT_EQ(mesh.colors[0].g, 1.0f);
  ASSERT_EQ(mesh.tangents.size(), 4u);  // read from the file as given
  EXPECT_EQ(mesh.tangents[0], glm::vec4(0, 1, 0, -1));
}

TEST(GltfMaterialImport, TransformRotationAndTexcoordOverride) {
  // The occlusion texture's transform is swapped for one with a rotation and a texCoord of its own.
  std::string text = replaced(read_bytes(asset("metal-rough-plane.gltf")), "\"strength\": 1.0,\n    \"extensions\"",
                              "\"strength\": 1.0, \"extensions\": {\"KHR_texture_transform\": {\"rotation\": 1.5, "
                              "\"texCoord\": 0}},\n    \"unused\"");
  World w = load(write_variant("rotated.gltf", text));
  const TextureRef& ref = w.materials()[0].occlusion_texture;
  EXPECT_NEAR(ref.rotation, 1.5f, 1e-5f);
  EXPECT_EQ(ref.texcoord, 0);
  EXPECT_EQ(ref.scale, glm::vec2(1, 1));
}

TEST(GltfMaterialImport, OptionalUnsupportedExtensionIsAWarning) {
  std::string text = replaced(read_bytes(asset("emissive-surface.gltf")), "\"KHR_materials_emissive_strength\"\n",
                              "\"KHR_materials_emissive_strength\",\n  \"KHR_materials_sheen\"\n");
  std::string path = write_variant("optional-extension.gltf", text);
  World w = load(path);
  EXPECT_EQ(w.materials().size(), 1u);
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0], path + ": the extension KHR_materials_sheen is not supported and was ignored");
}

TEST(GltfMaterialImport, RequiredUnsupportedExtensionIsAnError) {
  std::string text =
      replaced(read_bytes(asset("emissive-surface.gltf")), "\"extensionsUsed\"",
               "\"extensionsRequired\": [\"KHR_materials_emissive_strength\", \"KHR_draco_mesh_compression\"],\n "
               "\"extensionsUsed\"");
  std::string path = write_variant("required-extension.gltf", text);
  std::string error = error_of([&] { load(path); });
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("requires the extension KHR_draco_mesh_compression, which is not supported"), std::string::npos)
      << error;
}

TEST(GltfMaterialImport, TexcoordSetAboveOneIsAWarning) {
  std::string text =
      replaced(read_bytes(asset("normal-mapped-plane.gltf")), "\"scale\": 1.0", "\"scale\": 1.0, \"texCoord\": 2");
  std::string path = write_variant("texcoord-2.gltf", text);
  World w = load(path);
  EXPECT_EQ(w.materials()[0].normal_texture.texcoord, 0);
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("normalTexture uses TEXCOORD_2"), std::string::npos) << w.warnings[0];
}

}  // namespace
}  // namespace lg
