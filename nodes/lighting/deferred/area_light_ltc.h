// Area-light specular by linearly transformed cosines (Heitz et al. 2016): the GGX lobe at the
// view is replaced by the cosine lobe that M (ltc_table.h) carries into its shape, whose integral
// over a polygon is the Lambert polygon formula on the polygon carried back by M^-1 and clipped to
// the cosine's horizon. Float math, ported line by line to shaders/area_light_ltc.glsl.
// (The shader takes the outline's corners by a rotation from corner to corner, the same points
// up to rounding.)
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

// Segments of each end's arc of a capsule's outline (below), and the outline's vertices.
inline constexpr int kLtcArcSegments = 4;
inline constexpr int kLtcOutlineVertices = 2 * (kLtcArcSegments + 1);

// World directions to the LTC's cosine space at a surface: the frame of n (z) and v (x), then
// M^-1.
glm::mat3 ltc_to_cosine(glm::vec3 n, glm::vec3 v, glm::vec4 entry);

// I of a convex polygon, fed one edge at a time (either winding, relative to the shaded point)
// and clipped as it goes, without storing the polygon (the shaders have no cheap arrays): each
// edge is clipped to the horizon of the unit normal n (the GGX lobe is 0 below it, the fitted
// cosine not quite), carried into the cosine's space and clipped to its horizon, and the Lambert
// formula's term of what is left summed; where a clip cut the polygon, the edge along the plane
// from where it left to where it came back is added by ltc_finish.
struct LtcCosineClip {
  float sum = 0.0f;
  glm::vec3 exit{0.0f}, entry{0.0f};
  bool exited = false, entered = false;
};
struct LtcPolygon {
  glm::vec3 n{0.0f};
  glm::mat3 to_cosine{1.0f};
  glm::vec3 exit{0.0f}, entry{0.0f};
  bool exited = false, entered = false;
  LtcCosineClip cosine;
};
LtcPolygon ltc_polygon(glm::vec3 n, glm::vec3 v, glm::vec4 entry);
void ltc_add_cosine_edge(LtcCosineClip& c, glm::vec3 a, glm::vec3 b);
void ltc_add_edge(LtcPolygon& poly, glm::vec3 a, glm::vec3 b);
float ltc_finish(LtcPolygon& poly);

// The outline of a capsule with ends a and b (relative to the shaded point; a = b for a sphere)
// as it is seen: each end carried along its ray onto the plane through the centre facing the
// point, its sphere as the disk across that ray that subtends the sphere's cone, the ends' disks
// joined by the cylinder's silhouette lines; each end's arc runs between those lines' ends (a
// half circle from within the cylinder's reach) in kLtcArcSegments segments, its inner corners
// set out so that the arc's fan has the sector's area. A sphere (or a capsule seen end on) is one
// polygon of kLtcOutlineVertices sides of the disk's area. False for no outline (zero radius,
// or the point at the centre).
struct LtcOutline {
  glm::vec3 ends[2];
  float radii[2];      // of the ends' disks (the round polygon's corners)
  float spans[2];      // each end's arc: psi either side of its middle
  float inner[2];      // its inner corners' radius over radii
  glm::vec3 along;     // end 0 to end 1 in the plane facing the centre
  glm::vec3 axes[2];   // each end's arc: along, and sides, across the ray to that end
  glm::vec3 sides[2];
  bool round;          // one polygon around ends[0]
};
bool ltc_capsule_outline(glm::vec3 a, glm::vec3 b, float radius, glm::vec3 n, LtcOutline& outline);
glm::vec3 ltc_outline_vertex(const LtcOutline& outline, int j);

// I of the cone of directions to a sphere of the given radius centred at c (relative to the
// shaded point, outside it), wholly above the surface's horizon, without an outline: M^-1 makes
// it an elliptical cone, whose vector form factor F follows from its quadratic form. Where that
// cone is wholly above the cosine's horizon I = F.z exactly and this returns true; elsewhere
// false (the caller clips a polygon). to_cosine is ltc_to_cosine's.
bool ltc_cone_integral(glm::vec3 c, float radius, glm::mat3 to_cosine, float& integral);

float ltc_sphere_specular(const SphereLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);
float ltc_tube_specular(const TubeLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);
float ltc_rect_specular(const RectLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, glm::vec4 entry);

}  // namespace lg
