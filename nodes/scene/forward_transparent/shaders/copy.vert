#version 460
// One triangle over the whole target (vertices 0, 1, 2 from gl_VertexIndex): copy.frag fills
// the forward pass's target with its input before the transparent draws.
void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
