// The light lists of the deferred node (std140 uniform blocks, one per kind; light_buffers.cpp fills
// them from the scene) and the constants its passes share, at binding 0. The lists' bindings
// are in direct_lights.glsl and area_lights.glsl; scene.forward_transparent binds the same.
#ifndef LG_DEFERRED_LIGHTS_GLSL
#define LG_DEFERRED_LIGHTS_GLSL

#include "nodes/common/shaders/camera.glsl"

// Lights of each kind a frame shades at most (light_buffers.h's kMaxLightsPerKind): the lists are
// uniform blocks, since lavapipe loads a storage buffer one lane at a time even when every lane
// reads the same light; 256 of the largest (64 bytes) fill the 16 KB every device offers.
const int LG_MAX_LIGHTS = 256;

struct DirectionalLight {
  vec4 direction;  // xyz: unit, the way the light travels; w: 1 when it uses the shadow map
  vec4 irradiance;
};
struct PointLight {
  vec4 position_range;  // range 0: no cut-off
  vec4 intensity;       // w: its first shadow view, -1 for none (six views, a cube)
};
struct SpotLight {
  vec4 position_range;          // range 0: no cut-off
  vec4 direction_angle_scale;   // xyz: unit, the cone's axis; w: 1 / (cos inner - cos outer)
  vec4 intensity_angle_offset;  // rgb: W/sr on the axis; w: -cos outer * the scale
  vec4 shadow;                  // x: first shadow view, -1 for none; y: its views, 1 or 6 (a cube)
};
// One view of a point or spot light in the local shadow atlas (local_shadows.h).
struct ShadowView {
  mat4 clip_from_world;  // reversed Z: depth near / distance along the view
  vec4 tile;             // x, y: corner in the atlas, texels; z: edge, texels; w: texel size at distance 1
};
// An area light's w of `radiance` (a tube's of `end1`) is its first shadow view, -1 for none
// (six views, a cube about its centre).
struct SphereLight {
  vec4 center_radius;
  vec4 radiance;
};
struct TubeLight {
  vec4 end0_radius;
  vec4 end1;
  vec4 radiance;
};
struct RectLight {
  vec4 center_two_sided;  // w: 1 when it emits both ways
  vec4 half_x;
  vec4 half_y;
  vec4 radiance;
};

layout(std140, binding = 0) uniform Constants {
  Camera camera;
  mat4 shadow_from_world;  // to the shadow map's clip space (reversed depth)
  vec4 shadow;             // 1 / map size, 1 when the map was drawn, normal offset (world units), depth bias
  uvec4 counts;            // directional, point, sphere, tube (the rectangles' count is in counts2)
  uvec4 counts2;           // rectangles, spots
  vec4 local_shadow;       // 1 when the local shadow atlas was drawn, the views' near plane, area-light shadow taps
  vec4 brdf_albedo[512];   // the GGX lobe's (A, B) table, two texels a vec4 (brdf_albedo.glsl)
};

#include "nodes/env/brdf_lut/shaders/brdf_albedo.glsl"

#endif
