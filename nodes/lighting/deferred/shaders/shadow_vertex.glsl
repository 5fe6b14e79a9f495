// Depth from a light: a draw into the clip space of the shadow map or atlas tile; with
// LG_ALPHA_TEST (shadow_masked.vert) also what its alpha needs: both uv sets and the vertex colour.
#include "nodes/lighting/deferred/shaders/shadow_draw.glsl"

layout(location = 0) in vec3 position;
#ifdef LG_ALPHA_TEST
layout(location = 2) in vec2 uv;
layout(location = 3) in vec2 uv1;
layout(location = 5) in vec4 color;
layout(location = 0) out vec4 texcoords;  // set 0 in xy, set 1 in zw
layout(location = 1) out float vertex_alpha;
#endif

void main() {
  gl_Position = shadow_from_world * (this_draw.world * vec4(position, 1.0));
#ifdef LG_ALPHA_TEST
  texcoords = vec4(uv, uv1);
  vertex_alpha = color.a;
#endif
}
