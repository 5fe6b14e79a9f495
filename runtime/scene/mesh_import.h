// Importers of mesh files into a World: glTF 2.0 (.gltf with its buffers and images, or .glb)
// through tinygltf, and Wavefront OBJ with its MTL materials through tinyobjloader. They add
// meshes, materials and textures to the world's assets and entities for what the file places,
// parented under `parent` (null: the world's root), and return the top-level entities made.
// A corrupt, truncated or inconsistent file throws SceneError naming the file and what is
// wrong; the world may then hold some of the file's assets and entities.
//
// glTF: the default scene (else scene 0, else every root node) with its node hierarchy;
// triangle primitives only (points, lines, strips and fans are skipped); positions (float),
// normals (generated when missing), TEXCOORD_0 (float or normalised integers), indices of
// any integer type; metallic-roughness materials (factors, emissive, base colour texture
// decoded to RGBA8; the metallic-roughness, normal and occlusion textures are ignored);
// perspective cameras (orthographic ones are skipped); KHR_lights_punctual directional, point
// and spot lights (with their inner and outer cone angles; angles outside the spec's
// 0 <= inner < outer <= pi/2 are an error), intensities taken as the project's units
// (directional: irradiance, point and spot: W/sr). Sparse accessors, skins and morph
// targets are not supported. Buffers and images must lie in the file's folder or below.
//
// OBJ: positions, normals (generated when any corner lacks one), uvs (v flipped to glTF's
// top-left origin); one mesh per object and material. MTL to PBR: Kd is the base colour, d its
// alpha, Ke the emissive, Pm (the PBR extension) the metalness, and Ns the roughness by
// matching Blinn-Phong to GGX: alpha = sqrt(2 / (Ns + 2)), roughness = sqrt(alpha). Texture maps
// are not loaded. The geometry statements are checked strictly first (obj_syntax.h): a
// malformed or non-finite number, a bad face or an index out of range is an error at its line
// and column.
#pragma once

#include <string>
#include <vector>

#include "runtime/scene/world.h"

namespace lg {

std::vector<Entity> import_gltf(World& world, const std::string& path, Entity parent = {});
std::vector<Entity> import_obj(World& world, const std::string& path, Entity parent = {});

// Obj's Ns (specular exponent) as perceptual roughness in [0, 1].
float roughness_from_specular_exponent(float ns);

}  // namespace lg
