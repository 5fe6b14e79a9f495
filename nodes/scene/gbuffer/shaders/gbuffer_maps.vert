#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer's own vertex stage of textured or vertex-coloured draws: gbuffer.vert with the
// draw read from draw.glsl's uniform block, as gbuffer_plain.vert does (gbuffer.vert stays on
// the storage buffer for scene.forward_transparent and the reflection capture).
#define LG_MATERIAL_MAPS
#define LG_DRAW_BLOCK
#include "nodes/scene/gbuffer/shaders/gbuffer_vertex.glsl"
