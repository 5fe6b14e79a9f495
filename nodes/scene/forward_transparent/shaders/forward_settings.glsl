// The settings of the passes that shade with forward_shading.glsl (forward_bindings.h's
// ForwardSettings, std140).
#ifndef LG_FORWARD_SETTINGS_GLSL
#define LG_FORWARD_SETTINGS_GLSL

layout(std140, binding = 20) uniform Settings {
  uint flags;  // 1: image-based light, 2: its diffuse from SH (else the irradiance map)
  float intensity;
};

#endif
