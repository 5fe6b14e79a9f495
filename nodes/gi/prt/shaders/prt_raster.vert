#version 460
#extension GL_GOOGLE_include_directive : require
// gi.prt's drawing: transforms one draw as the G-buffer pass does and passes on its
// vertices' irradiance and validity (prt_vertices.comp), interpolated across each triangle.
#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(std430, binding = 2) readonly buffer DrawBases { uint draw_base[]; };  // first vertex of each draw
layout(std430, binding = 3) readonly buffer VertexIrradiance { vec4 vertex_irradiance[]; };

layout(location = 0) in vec3 position;
layout(location = 0) out vec4 irradiance;

void main() {
  Draw d = draws[draw_index];
  irradiance = vertex_irradiance[draw_base[draw_index] + uint(gl_VertexIndex)];
  gl_Position = camera.view_projection * (d.world * vec4(position, 1.0));
}
