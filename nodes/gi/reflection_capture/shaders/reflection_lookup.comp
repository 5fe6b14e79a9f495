#version 460
#extension GL_GOOGLE_include_directive : require
// gi.reflection_capture's lookup: per G-buffer pixel the radiance reflected toward the eye
// before the BRDF, from the scene's prefiltered probe cubes: the reflection of the view about the
// normal, corrected for parallax by each probe's proxy (reflection_probes.glsl) when asked, read
// at the mip of the pixel's roughness (as lighting.ibl reads the environment's prefiltered map),
// overlapping probes weighted by their influence. rgb: the weighted mean, a: the summed weight
// clamped to 1 (the coverage lighting.ibl mixes the environment toward it by); 0 on the sky and
// outside every probe.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/gi/reflection_capture/shaders/reflection_probes.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D material_tex;  // r: perceptual roughness
layout(std140, binding = 4) uniform Probes { ReflectionProbe probes[LG_MAX_REFLECTION_PROBES]; };
layout(binding = 5) uniform samplerCubeArray cubes;  // cube i: probe i, prefiltered, mip m roughness m / (mips - 1)
layout(binding = 6, rgba16f) uniform writeonly image2D reflections;
layout(constant_id = 0) const bool parallax = true;
layout(push_constant) uniform Push {  // reflection_capture_kernel.cpp
  uint probe_count;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(reflections)))) return;
  float depth = texelFetch(depth_tex, texel, 0).r;
  if (depth <= 0.0) {
    imageStore(reflections, texel, vec4(0.0));
    return;
  }
  vec3 p = world_position(camera, texel, depth);
  vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
  vec3 r = reflect(-normalize(camera.position.xyz - p), n);
  float lod = texelFetch(material_tex, texel, 0).r * float(textureQueryLevels(cubes) - 1);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < min(int(probe_count), LG_MAX_REFLECTION_PROBES); ++i) {
    float w = probe_weight(probes[i], p);
    if (w <= 0.0) continue;
    vec3 d = parallax ? parallax_direction(probes[i], p, r) : r;
    sum += w * textureLod(cubes, vec4(d, float(i)), lod).rgb;
    weights += w;
  }
  vec3 radiance = weights > 0.0 ? sum / weights : vec3(0.0);
  imageStore(reflections, texel, vec4(radiance, min(weights, 1.0)));
}
