#version 460
#extension GL_GOOGLE_include_directive : require
// The raster captures' background, drawn over each cube face (or mirrored view) before its meshes: the environment
// as lighting.ibl shows the sky (the prefiltered map's mip 0 times the intensity), black without
// image-based light. Vertex stage: scene.forward_transparent's full-screen copy.vert.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/lighting/ibl/shaders/ibl_environment.glsl"
#include "nodes/scene/forward_transparent/shaders/forward_settings.glsl"

layout(std140, binding = 0) uniform Constants { Camera camera; };  // lights.glsl's block begins so

layout(location = 0) out vec4 out_color;

void main() {
  vec3 direction = world_position(camera, ivec2(gl_FragCoord.xy), 1.0) - camera.position.xyz;
  vec3 sky = (flags & 1u) != 0u ? intensity * textureLod(specular_map, direction, 0.0).rgb : vec3(0.0);
  out_color = vec4(finite_or_zero(sky), (flags & 4u) != 0u ? 65504.0 : 1.0);  // the sky: as far as half floats go
}
