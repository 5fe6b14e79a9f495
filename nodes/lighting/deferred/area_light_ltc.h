// Area-light specular by linearly transformed cosines (Heitz et al. 2016): the GGX lobe at the
// view is replaced by the cosine lobe that M (ltc_table.h) carries into its shape, whose integral
// over a polygon is the Lambert polygon formula on the polygon carried back by M^-1 and clipped to
// the cosine's horizon. Float math, ported line by line to shaders/area_light_ltc.glsl.
// (The shader takes the outline's corners by a rotation from corner to corner, the same points
// up to rounding.)
//
// Each returns L I: the light's radiance times the fraction of the lobe's energy the light covers
// (I in [0, 1]). The specular radiance toward v is that times the lobe's directional albedo
// (with Fresnel and the multiple-scattering scale: brdf_energy.glsl's specular_albedo). I is the
// LTC's integral corrected for the LTC's shape at the light (ltc_shape_corrected). Degenerate
// input (a zero or NaN normal, a light of zero size, a point on a light's plane or inside it)
// returns a finite value in [0, L].
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "nodes/lighting/deferred/area_light.h"

namespace lg {

// The GGX lobe at a view as the LTC specular reads it, once a pixel: the table's entry
// (ltc_lookup(n.v, roughness)), and for the exact lobe where the LTC's shape is corrected alpha,
// the lobe's directional albedo E = A + B with Fresnel 1, and the view in the frame of n and v,
// (sqrt(1 - n.v^2), 0, n.v).
struct LtcLobe {
  glm::vec4 entry{0.0f};
  float alpha = 0.0f;
  float albedo = 1.0f;
  glm::vec3 view{0.0f, 0.0f, 1.0f};
};
LtcLobe ltc_lobe(float n_dot_v, float roughness);

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
  glm::vec3 sum{0.0f};  // the Lambert formula's edge vectors: 2 pi F, F the vector form factor
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

// The vector form factor F of the cone of directions to a sphere of the given radius centred at
// c (relative to the shaded point, outside it), wholly above the surface's horizon, without an
// outline: M^-1 makes it an elliptical cone, whose F follows from its quadratic form. Where that
// cone is wholly above the cosine's horizon I = F.z exactly and this returns true; elsewhere
// false (the caller clips a polygon). to_cosine is ltc_to_cosine's.
bool ltc_cone_form_factor(glm::vec3 c, float radius, glm::mat3 to_cosine, glm::vec3& form_factor);

// The LTC's integral I = F.z over a light whose vector form factor in the cosine's space is F, scaled
// by the exact lobe over the LTC at F's direction carried back by M: the LTC's shape is off the
// GGX lobe's by up to tens of percent pointwise (its tails, grazing views), and a small light
// gathers that pointwise error, which the ratio removes. A large light's I is already close
// (the LTC integrates to the lobe's energy), and one direction does not speak for it: the ratio
// is weighed by exp(-5 |F|) (|F| is about the light's solid angle over pi in the cosine's space
// while it is small), the plain I by the rest. Measured on the benchmark's points (README.md).
float ltc_shape_corrected(glm::vec3 form_factor, const LtcLobe& lobe);

float ltc_sphere_specular(const SphereLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, const LtcLobe& lobe);
float ltc_tube_specular(const TubeLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, const LtcLobe& lobe);
float ltc_rect_specular(const RectLight& light, glm::vec3 p, glm::vec3 n, glm::vec3 v, const LtcLobe& lobe);

}  // namespace lg
