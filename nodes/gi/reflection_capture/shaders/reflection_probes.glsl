// The reflection probes as gi.reflection_capture's lookup reads them (reflection_probe_buffer.h
// fills the std140 array): influence weights with their blend, and the parallax correction that
// intersects the reflection ray with a probe's proxy.
#ifndef LG_REFLECTION_PROBES_GLSL
#define LG_REFLECTION_PROBES_GLSL

const uint LG_PROBE_BOX = 0u;
const uint LG_PROBE_SPHERE = 1u;
const int LG_MAX_REFLECTION_PROBES = 16;  // reflection_probe_buffer.h: kMaxReflectionProbes

struct ReflectionProbe {
  mat4 to_local;      // world to the entity's frame
  mat4 to_world;      // the entity's frame to world; its origin is where the cube was taken
  vec4 influence;     // xyz: box half sizes, or x: sphere radius; w: blend, metres
  vec4 proxy;         // xyz: box half sizes, or x: sphere radius
  vec4 proxy_offset;  // xyz: the proxy's centre in the entity's frame
  uvec4 shapes;       // x: the influence's shape, y: the proxy's (LG_PROBE_BOX, LG_PROBE_SPHERE)
};

// How far inside the shape (half sizes or radius) the local point q is; negative outside.
float probe_shape_depth(uint shape, vec3 half_size, vec3 q) {
  if (shape == LG_PROBE_SPHERE) return half_size.x - length(q);
  vec3 d = half_size - abs(q);
  return min(d.x, min(d.y, d.z));
}

// The probe's weight at world point p: 1 deeper inside than the blend distance, falling to 0 at
// the boundary (a hard edge when the blend is 0).
float probe_weight(ReflectionProbe probe, vec3 p) {
  vec3 q = (probe.to_local * vec4(p, 1.0)).xyz;
  float depth = probe_shape_depth(probe.shapes.x, probe.influence.xyz, q);
  float blend = probe.influence.w;
  return blend > 0.0 ? clamp(depth / blend, 0.0, 1.0) : (depth >= 0.0 ? 1.0 : 0.0);
}

// The direction from the probe's centre toward where the ray p + t r (t > 0) leaves the proxy:
// what the cube saw there. Points on or just outside the proxy (a floor the proxy's face lies on)
// take the exit of a ray that enters it; a ray that misses the proxy keeps r.
vec3 parallax_direction(ReflectionProbe probe, vec3 p, vec3 r) {
  vec3 o = (probe.to_local * vec4(p, 1.0)).xyz - probe.proxy_offset.xyz;
  vec3 d = mat3(probe.to_local) * r;
  float t = -1.0;
  if (probe.shapes.y == LG_PROBE_SPHERE) {
    // |o + t d|^2 = R^2, the far root.
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - probe.proxy.x * probe.proxy.x;
    float disc = b * b - a * c;
    if (disc >= 0.0 && a > 0.0) t = (-b + sqrt(disc)) / a;
  } else {
    // Slabs: the ray is inside the box between the largest near plane and the smallest far one.
    vec3 safe = mix(vec3(1e-20), d, greaterThan(abs(d), vec3(1e-20)));
    vec3 t1 = (-probe.proxy.xyz - o) / safe, t2 = (probe.proxy.xyz - o) / safe;
    vec3 near_planes = min(t1, t2), far_planes = max(t1, t2);
    float t_near = max(near_planes.x, max(near_planes.y, near_planes.z));
    float t_far = min(far_planes.x, min(far_planes.y, far_planes.z));
    if (t_far >= t_near) t = t_far;
  }
  if (!(t > 0.0)) return r;
  vec3 hit = (probe.to_world * vec4(o + t * d + probe.proxy_offset.xyz, 1.0)).xyz;
  vec3 from_centre = hit - probe.to_world[3].xyz;
  return dot(from_centre, from_centre) > 1e-12 ? from_centre : r;
}

#endif
