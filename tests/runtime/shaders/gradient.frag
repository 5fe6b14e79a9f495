// Colours each pixel with its normalised centre coordinate (exact in half precision for
// power-of-two sizes) and, in blue, the depth it was drawn at.
#version 460
layout(push_constant) uniform Constants { vec2 size; float depth; };
layout(location = 0) out vec4 color;

void main() {
  color = vec4(gl_FragCoord.xy / size, depth, 1);
}
