// The settings of the passes that shade with forward_shading.glsl (forward_bindings.h's
// ForwardSettings, std140).
#ifndef LG_FORWARD_SETTINGS_GLSL
#define LG_FORWARD_SETTINGS_GLSL

layout(std140, binding = 20) uniform Settings {
  uint flags;  // 1: image-based light, 2: its diffuse from SH (else the irradiance map), 4: the
               // captures write the distance to the camera in alpha (a planar reflection's blur)
  float intensity;
  float volume_normal_bias, volume_view_bias;  // the captures' probe volume lookup, in cells
  vec4 clip_plane;  // the captures draw only where dot(clip_plane, (p, 1)) >= 0: a mirror's front
  uint volume_count;  // the captures' probe volumes (capture_surface.glsl)
};

#endif
