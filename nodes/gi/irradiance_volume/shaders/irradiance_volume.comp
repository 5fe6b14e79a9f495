#version 460
#extension GL_GOOGLE_include_directive : require
// gi.irradiance_volume's lookup: per texel of its target the irradiance from the scene's probe
// volumes (probe_volume.glsl's lookup_volumes), rgb in W/m^2 and a the coverage; 0 on the sky
// and outside every volume. The target is the output itself, or at resolution_scale 1/k below 1 a
// smaller image whose texel i is the G-buffer's texel upsample_source_texel(i, k) (upsample.comp
// brings it back to full resolution).
#define LG_PROBE_VOLUME_BINDING 3
#define LG_PROBE_RECORD_BINDING 4
#define LG_PROBE_IRRADIANCE_BINDING 5
#define LG_PROBE_DISTANCE_BINDING 6
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"
#include "nodes/gi/irradiance_volume/shaders/probe_volume.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };  // at the G-buffer's size
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 7, rgba16f) uniform writeonly image2D irradiance;
layout(constant_id = 0) const uint representation = LG_PROBE_OCTAHEDRAL;  // ProbeRepresentation
layout(constant_id = 1) const bool visibility = true;
layout(push_constant) uniform Push {  // irradiance_volume_kernel.cpp
  uint volume_count;
  float normal_bias;
  float view_bias;
  int k;  // the G-buffer's resolution over the target's
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(irradiance)))) return;
  ivec2 source = upsample_source_texel(texel, k, textureSize(depth_tex, 0));
  float depth = texelFetch(depth_tex, source, 0).r;
  if (depth <= 0.0) {
    imageStore(irradiance, texel, vec4(0.0));
    return;
  }
  vec3 p = world_position(camera, source, depth);
  vec3 n = decode_normal(texelFetch(normal_tex, source, 0).rgb);
  ProbeLookup s = ProbeLookup(representation, visibility, normal_bias, view_bias);
  imageStore(irradiance, texel, lookup_volumes(int(volume_count), p, n, camera.position.xyz, s));
}
