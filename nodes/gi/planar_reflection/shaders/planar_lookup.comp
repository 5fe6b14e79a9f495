#version 460
#extension GL_GOOGLE_include_directive : require
// gi.planar_reflection's lookup (docs/planar-reflections.md). A G-buffer pixel on a drawn
// reflector plane (within a millimetre and a thousandth of its distance, its normal within 25
// degrees of the plane's: a normal map keeps it on) reads the plane's mirrored view at its own
// screen position: rgb the reflected radiance before the BRDF, a 1. A rough surface reads it
// blurred: its GGX lobe, taken as a cone of tangent alpha (roughness^2) about the mirror
// direction, spreads over `beyond` * alpha at the reflected surface, `beyond` metres past the
// mirror (from the distance the view holds in alpha); that width in texels of the view picks the
// level of the chain. Other pixels keep the input's reflections, or 0.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

const int LG_MAX_PLANES = 8;  // planar_reflection_kernel.cpp: kMaxPlanes

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D material_tex;  // r: perceptual roughness
layout(std140, binding = 4) uniform Planes { vec4 planes[LG_MAX_PLANES]; };  // xyz unit normal, w: n . p + w = 0
layout(binding = 5) uniform sampler2DArray views;  // layer i: plane i's mirrored view; a: distance from its camera
layout(binding = 6) uniform sampler2D under;       // the input reflections (has_under)
layout(binding = 7, rgba16f) uniform writeonly image2D reflections;
layout(push_constant) uniform Push {  // planar_reflection_kernel.cpp
  uint plane_count;
  uint has_under;
  float texel_angle;  // of a mirrored view's texel at its centre, radians
};

// The drawn plane the surface at p with normal n lies on, or -1.
int plane_of(vec3 p, vec3 n, float eye_distance) {
  float tolerance = 1e-3 + 1e-3 * eye_distance;
  for (int i = 0; i < min(int(plane_count), LG_MAX_PLANES); ++i)
    if (abs(dot(planes[i].xyz, p) + planes[i].w) < tolerance && dot(n, planes[i].xyz) > 0.9) return i;
  return -1;
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(reflections)))) return;
  vec4 result = has_under != 0u ? texelFetch(under, texel, 0) : vec4(0.0);
  float depth = texelFetch(depth_tex, texel, 0).r;
  if (depth > 0.0) {
    vec3 p = world_position(camera, texel, depth);
    float eye_distance = distance(camera.position.xyz, p);
    int plane = plane_of(p, decode_normal(texelFetch(normal_tex, texel, 0).rgb), eye_distance);
    if (plane >= 0) {
      vec2 uv = (vec2(texel) + 0.5) * camera.viewport.zw;
      ivec2 view_size = textureSize(views, 0).xy;
      ivec2 view_texel = min(ivec2(uv * vec2(view_size)), view_size - 1);
      float hit_distance = max(texelFetch(views, ivec3(view_texel, plane), 0).a, eye_distance);
      float roughness = clamp(texelFetch(material_tex, texel, 0).r, 0.0, 1.0);
      float spread = (hit_distance - eye_distance) * roughness * roughness / (hit_distance * texel_angle);
      float lod = log2(max(2.0 * spread, 1.0));
      result = vec4(textureLod(views, vec3(uv, float(plane)), lod).rgb, 1.0);
    }
  }
  imageStore(reflections, texel, result);
}
