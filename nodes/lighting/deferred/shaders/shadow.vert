#version 460
// Depth from a light: positions only, into the clip space of the shadow map or atlas tile.
layout(location = 0) in vec3 position;

layout(std430, binding = 0) readonly buffer Worlds { mat4 worlds[]; };
layout(push_constant) uniform Push {
  mat4 shadow_from_world;
  uint draw_index;
};

void main() {
  gl_Position = shadow_from_world * (worlds[draw_index] * vec4(position, 1.0));
}
