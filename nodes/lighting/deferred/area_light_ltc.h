// Area-light specular by linearly transformed cosines (Heitz et al. 2016): the GGX lobe at the
// view is replaced by the cosine lobe that M (ltc_table.h) carries into its shape, whose integral
// over a polygon is the Lambert polygon formula on the polygon carried back by M^-1 and clipped to
// the cosine's horizon. Float math, ported line by line to shaders/area_light_ltc.glsl.
//
// Each returns L I: the light's radiance times the fraction of the lobe's energy the light covers
// (I in [0, 1]). The specular radiance toward v is that times the lobe's directional albedo
// (with Fresnel and the multiple-scattering scale: brdf_energy.glsl's specular_albedo). `entry`
// is ltc_lookup(n.v, roughness). Degenerate input (a zero or NaN normal, a light of zero size, a
// point on a light's plane or inside it) returns a finite value in [0, L].
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "nodes/lighting/deferred/area_light.h"

namespace lg {

// Segments of each half circle of a sphere's or capsule's outline (below).
inline constexpr int kLtcArcSegments = 4;
// The most vertices an outline has (2 (arc segments + 1)), and room for what two clips add.
inline constexpr int kLtcMaxVertices = 16;

// World directions to the LTC's cosine space at a surface: the frame of n (z) and v (x), then
// M^-1.
glm::mat3 ltc_to_cosine(glm::vec3 n, glm::vec3 v, glm::vec4 entry);

// I for a polygon of `count` vertices (at most 2 (kLtcArcSegments + 1)), given relative to the
// shaded point, either winding: clipped to the horizon of the unit normal n (the GGX lobe is 0
// below it, the fitted cosine not quite), carried into the cosine's space and clipped to its
// horizon.
float ltc_polygon_integral(const glm::vec3* vertices, int count, glm::vec3 n, const glm::mat3& to_cosine);

// The outline of a capsule with ends a and b (relative to the shaded point; a = b for a sphere)
// as it is seen, laid in the plane through its centre facing the point: each end's sphere as the
// disk there that subtends its cone, the ends' disks joined by their tangent lines; a half circle
// is a half polygon of kLtcArcSegments segments of the same area. Returns the vertex count.
int ltc_capsule_outline(glm::vec3 a, glm::vec3 b, float radius, glm::vec3 n, glm::vec3* vertices);

float ltc_sphere_specular(const SphereLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);
float ltc_tube_specular(const TubeLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);
float ltc_rect_specular(const RectLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);

}  // namespace lg
