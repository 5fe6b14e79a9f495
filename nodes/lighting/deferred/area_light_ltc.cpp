#include "nodes/lighting/deferred/area_light_ltc.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "nodes/env/brdf_lut/dfg_reference.h"
#include "nodes/lighting/deferred/area_light_math.h"
#include "nodes/lighting/deferred/ltc_table.h"

namespace lg {
namespace {

using glm::vec3;

vec3 any_perpendicular(vec3 n) {
  return glm::normalize(glm::cross(n, std::fabs(n.x) < 0.7f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
}

float specular_result(float radiance, float integral) {
  return finite_or_zero(std::max(radiance, 0.0f) * clamp01(finite_or_zero(integral)));
}

}  // namespace

LtcLobe ltc_lobe(float n_dot_v, float roughness) {
  const float sin_v = std::sqrt(std::max(1.0f - n_dot_v * n_dot_v, 0.0f));
  return {ltc_lookup(n_dot_v, roughness), float(ltc_alpha(roughness)),
          float(white_albedo(brdf_albedo_lookup(n_dot_v, roughness))), vec3(sin_v, 0.0f, n_dot_v)};
}

glm::mat3 ltc_to_cosine(vec3 n, vec3 v, glm::vec4 entry) {
  n = glm::normalize(n);
  vec3 t1 = v - n * glm::dot(n, v);
  const float len = glm::length(t1);
  // Seen straight on, any tangent serves: the lobe is round there.
  t1 = len > 1e-6f ? t1 / len : any_perpendicular(n);
  const vec3 t2 = glm::cross(n, t1);
  return ltc_inverse(entry) * glm::transpose(glm::mat3(t1, t2, n));
}

namespace {

// The Lambert formula's term of edge a-b: its angle times its unit normal (the z of which
// integrates the cosine; the whole vector gives the vector form factor's direction).
vec3 edge_term(vec3 a, vec3 b) {
  const vec3 e0 = glm::normalize(a), e1 = glm::normalize(b);
  const vec3 c = glm::cross(e0, e1);
  const float s = glm::length(c);
  // atan2 keeps the angle exact for short edges, where acos of the dot product loses it.
  return s > 0.0f ? c * std::atan2(s, glm::dot(e0, e1)) / s : vec3(0.0f);
}

// Where edge a-b crosses the plane through the origin at signed distances da, db (a's, b's);
// a when they do not straddle it, so that the callers' selects never see a division by zero.
vec3 crossing(vec3 a, vec3 b, float da, float db) {
  const float denom = da - db;
  return a + (b - a) * (denom != 0.0f ? da / denom : 0.0f);
}

}  // namespace

// The clips choose the kept part's ends by selects and take one edge term, not one per case, as
// the shader does (a GPU, lavapipe too, runs every side of a branch its lanes disagree on).
void ltc_add_cosine_edge(LtcCosineClip& c, vec3 a, vec3 b) {
  const bool a_in = a.z > 0.0f, b_in = b.z > 0.0f;
  const vec3 x = crossing(a, b, a.z, b.z);
  if (a_in && !b_in) c.exit = x, c.exited = true;
  if (b_in && !a_in) c.entry = x, c.entered = true;
  const vec3 term = edge_term(a_in ? a : x, b_in ? b : x);
  c.sum += a_in || b_in ? term : vec3(0.0f);
}

void ltc_add_edge(LtcPolygon& poly, vec3 a, vec3 b) {
  const float da = glm::dot(poly.n, a), db = glm::dot(poly.n, b);
  const bool a_in = da > 0.0f, b_in = db > 0.0f;
  const vec3 x = crossing(a, b, da, db);
  if (a_in && !b_in) poly.exit = x, poly.exited = true;
  if (b_in && !a_in) poly.entry = x, poly.entered = true;
  // An edge wholly below the horizon becomes the point x, which adds nothing.
  ltc_add_cosine_edge(poly.cosine, poly.to_cosine * (a_in ? a : x), poly.to_cosine * (b_in ? b : x));
}

float ltc_finish(LtcPolygon& poly) {
  // The horizon's chord where the surface clip cut the polygon (a point, adding nothing, where not).
  const bool cut = poly.exited && poly.entered;
  ltc_add_cosine_edge(poly.cosine, poly.to_cosine * poly.exit, poly.to_cosine * (cut ? poly.entry : poly.exit));
  LtcCosineClip& c = poly.cosine;
  const vec3 chord = edge_term(c.exit, c.entry);
  c.sum += c.exited && c.entered ? chord : vec3(0.0f);
  return std::fabs(c.sum.z) / (2.0f * kAreaLightPi);
}

namespace {

// F of a finished polygon, oriented so that F.z = I (the winding decides the sum's sign).
vec3 form_factor(const LtcPolygon& poly) {
  return poly.cosine.sum * ((poly.cosine.sum.z < 0.0f ? -1.0f : 1.0f) / (2.0f * kAreaLightPi));
}

}  // namespace

LtcPolygon ltc_polygon(vec3 n, vec3 v, glm::vec4 entry) {
  LtcPolygon poly;
  poly.n = glm::normalize(n);
  poly.to_cosine = ltc_to_cosine(n, v, entry);
  return poly;
}

bool ltc_capsule_outline(vec3 a, vec3 b, float radius, vec3 n, LtcOutline& o) {
  const vec3 c = 0.5f * (a + b);
  const float dc = glm::length(c);
  if (!(dc > 0.0f) || !(radius > 0.0f)) return false;
  const vec3 u = c / dc;
  o.ends[0] = a, o.ends[1] = b;
  for (int k = 0; k < 2; ++k) {
    const vec3 e = o.ends[k];
    // Along the ray to the end, onto the plane (an end beside or behind the point is held in front).
    const float depth = std::max(glm::dot(e, u), 1e-3f * dc);
    const float scale = dc / depth;
    o.ends[k] = e * scale + u * (dc - glm::dot(e, u) * scale);
    // Its sphere's cone has tan = r / sqrt(d^2 - r^2) (held finite inside the sphere).
    const float d2 = glm::dot(e, e);
    o.radii[k] = radius * std::sqrt(d2) * scale / std::sqrt(std::max(d2 - radius * radius, 1e-6f * d2));
  }
  const vec3 axis = o.ends[1] - o.ends[0];
  const float len = glm::length(axis);
  o.round = !(len > 1e-6f * dc);
  if (!o.round) {
    o.along = axis / len;
  } else {
    // A sphere, or a capsule seen end on: its outline is round; one polygon edge lies along the
    // horizon's trace for symmetry.
    const vec3 in_plane = n - u * glm::dot(n, u);
    o.along = glm::length(in_plane) > 1e-6f ? glm::normalize(in_plane) : any_perpendicular(u);
    // One polygon of kLtcOutlineVertices sides, none wasted on zero-length edges where two arcs
    // would meet (a sphere at roughness 0.15 that gathers 0.64 of the lobe read 4.4% high as an
    // 8-gon); the disk's area: R^2 N sin(2 pi / N) / 2 = pi r^2.
    const float sides = float(kLtcOutlineVertices);
    o.radii[0] = o.radii[1] = std::max(o.radii[0], o.radii[1]) *
                              std::sqrt(2.0f * kAreaLightPi / (sides * std::sin(2.0f * kAreaLightPi / sides)));
  }
  // Each end's arc lies across the ray to that end (the cross-section of its sphere's cone), not
  // in the plane facing the centre: seen obliquely and near, the flat outline read a capsule up
  // to 18% low.
  for (int k = 0; k < 2; ++k) {
    const vec3 w = glm::normalize(o.ends[k]);
    const vec3 across = o.along - w * glm::dot(o.along, w);
    const float across_len = glm::length(across);
    o.axes[k] = across_len > 1e-6f ? across / across_len : o.along;
    o.sides[k] = glm::normalize(glm::cross(w, o.axes[k]));
  }
  // The cylinder's silhouette is two of its lines, where the planes through the point and
  // tangent to it touch: at h from the axis they lie r^2 / h towards the point and
  // r sqrt(1 - r^2 / h^2) to each side. Each end's arc runs between those lines' ends, on the
  // side away from the other end: psi either side of its middle, more than a half circle where
  // the point is near and sees the tube obliquely (half circles there put the junctions off the
  // silhouette: the benchmark's tubes across the horizon 0.45 -> 0.29). Within the cylinder's
  // reach (h <= r; capsule_specular then passes a sphere) half circles.
  const vec3 dir = o.round ? vec3(0.0f) : glm::normalize(b - a);
  const vec3 foot = a - dir * glm::dot(a, dir);
  const float h = glm::length(foot);
  const bool beside = !o.round && h > radius * 1.0001f;
  // (Held finite where unused: on the axis line, or within the cylinder's reach.)
  const vec3 toward = h > 0.0f ? -foot / h : vec3(0.0f), side = glm::cross(dir, toward);
  const float ratio = radius / std::max(h, radius);
  const vec3 offset = radius * (ratio * toward + std::sqrt(1.0f - ratio * ratio) * side);
  for (int k = 0; k < 2; ++k) {
    const vec3 touch = (k == 0 ? a : b) + offset;
    const float along_ray = glm::dot(touch, glm::normalize(o.ends[k]));
    const vec3 q = touch * (glm::length(o.ends[k]) / along_ray) - o.ends[k];
    const float psi = std::atan2(std::fabs(glm::dot(q, o.sides[k])), (k == 0 ? -1.0f : 1.0f) * glm::dot(q, o.axes[k]));
    o.spans[k] = beside && along_ray > 0.0f ? psi : 0.5f * kAreaLightPi;
    // The arc's inner corners at rho R, its ends on the lines at R: the fan of kLtcArcSegments
    // triangles then has the sector's area, R^2 psi (sin(step) R^2 (2 rho + (K - 2) rho^2) / 2).
    const float segments = float(kLtcArcSegments), step = 2.0f * o.spans[k] / segments;
    o.inner[k] = (std::sqrt(1.0f + (segments - 2.0f) * 2.0f * o.spans[k] / std::sin(step)) - 1.0f) / (segments - 2.0f);
  }
  return true;
}

vec3 ltc_outline_vertex(const LtcOutline& o, int j) {
  if (o.round) {
    const float angle = 0.5f * kAreaLightPi + 2.0f * kAreaLightPi * float(j) / float(kLtcOutlineVertices);
    return o.ends[0] + o.radii[0] * (std::cos(angle) * o.axes[0] + std::sin(angle) * o.sides[0]);
  }
  // End 0's arc faces away from end 1 (about -along), end 1's about +along.
  const int half = j / (kLtcArcSegments + 1), i = j - half * (kLtcArcSegments + 1);
  const float middle = half == 0 ? kAreaLightPi : 0.0f;
  const float angle = middle - o.spans[half] + 2.0f * o.spans[half] * float(i) / float(kLtcArcSegments);
  const float r = o.radii[half] * (i == 0 || i == kLtcArcSegments ? 1.0f : o.inner[half]);
  return o.ends[half] + r * (std::cos(angle) * o.axes[half] + std::sin(angle) * o.sides[half]);
}

namespace {

// F of the outline's polygon (zero for no outline).
vec3 capsule_form_factor(vec3 a, vec3 b, float radius, vec3 n, vec3 v, glm::vec4 entry) {
  LtcOutline o;
  if (!ltc_capsule_outline(a, b, radius, n, o)) return vec3(0.0f);
  LtcPolygon poly = ltc_polygon(n, v, entry);
  vec3 previous = ltc_outline_vertex(o, kLtcOutlineVertices - 1);
  for (int j = 0; j < kLtcOutlineVertices; ++j) {
    const vec3 next = ltc_outline_vertex(o, j);
    ltc_add_edge(poly, previous, next);
    previous = next;
  }
  ltc_finish(poly);
  return form_factor(poly);
}

}  // namespace

bool ltc_cone_form_factor(vec3 c, float radius, glm::mat3 to_cosine, vec3& form_factor) {
  // The sphere's cone of directions is the cone over the disk across the ray to its centre, of
  // tangent r / sqrt(d^2 - r^2); M^-1 carries the disk to an ellipse and the cone to an
  // elliptical cone (scaled so that the centre's image is a unit vector).
  const float d2 = glm::dot(c, c);
  const float tan_a = radius / std::sqrt(std::max(d2 - radius * radius, 1e-6f * d2));
  const vec3 w = c / std::sqrt(d2);
  const vec3 e1 = any_perpendicular(w), e2 = glm::cross(w, e1);
  const vec3 centre = to_cosine * w;
  const float scale = 1.0f / glm::length(centre);
  const vec3 axis0 = centre * scale, v1 = to_cosine * e1 * (tan_a * scale), v2 = to_cosine * e2 * (tan_a * scale);
  // Its directions x = A y with A = [v1 v2 axis0], y1^2 + y2^2 <= y3^2, J = diag(1, 1, -1): the
  // cone x^T P^-1 x <= 0 with P = A J A^T, whose eigenvalues are (in the cone's frame, tangents
  // a and b) a^2, b^2 and -1 up to scale. P, not P^-1: a far light's a^2 would be lost beside
  // P^-1's 1 / a^2 in float; P's negative eigenvalue p3 dominates and is found accurately.
  const glm::mat3 pm = glm::outerProduct(v1, v1) + glm::outerProduct(v2, v2) - glm::outerProduct(axis0, axis0);
  // p3, the symmetric cubic's smallest root by its trigonometric solution, and its eigenvector,
  // the cone's axis.
  const float mean = (pm[0][0] + pm[1][1] + pm[2][2]) / 3.0f;
  const float off = pm[1][0] * pm[1][0] + pm[2][0] * pm[2][0] + pm[2][1] * pm[2][1];
  const vec3 diag = vec3(pm[0][0], pm[1][1], pm[2][2]) - mean;
  const float spread = std::sqrt(std::max((glm::dot(diag, diag) + 2.0f * off) / 6.0f, 1e-30f));
  const float half_det = std::min(std::max(0.5f * glm::determinant((pm - glm::mat3(mean)) / spread), -1.0f), 1.0f);
  const float p3 = mean + 2.0f * spread * std::cos(std::acos(half_det) / 3.0f + 2.0f * kAreaLightPi / 3.0f);
  const glm::mat3 shifted = pm - glm::mat3(p3);
  const vec3 c01 = glm::cross(shifted[0], shifted[1]), c02 = glm::cross(shifted[0], shifted[2]),
             c12 = glm::cross(shifted[1], shifted[2]);
  const float l01 = glm::dot(c01, c01), l02 = glm::dot(c02, c02), l12 = glm::dot(c12, c12);
  const vec3 axis = l01 > l02 ? (l01 > l12 ? c01 : c12) : (l02 > l12 ? c02 : c12);
  const vec3 axis_dir = glm::normalize(glm::dot(axis, axis0) < 0.0f ? -axis : axis);
  // The elliptical cone's vector form factor F lies along its axis, of length
  // ab / sqrt((1 + a^2)(1 + b^2)) = sqrt(p1 p2 / ((p1 - p3)(p2 - p3))), where
  // p1 p2 p3 = det P = -det(A)^2 and the product below is the characteristic polynomial's slope
  // at p3 (Heitz and Hill 2017 integrate disks this way). Wholly above the cosine's horizon the
  // clamped cosine's integral is F.z exactly.
  const float det_a = glm::dot(v1, glm::cross(v2, axis0));
  const float minors = pm[0][0] * pm[1][1] + pm[0][0] * pm[2][2] + pm[1][1] * pm[2][2] - off;
  const float slope = 3.0f * p3 * p3 - 6.0f * mean * p3 + minors;
  form_factor = clamp01(std::fabs(det_a) / std::sqrt(std::max(-p3 * slope, 1e-30f))) * axis_dir;
  // The cone misses the plane z = 0 where P^-1's block on that plane is positive definite, i.e.
  // (det P < 0) the same block of P's adjugate is negative definite.
  const float adj00 = pm[1][1] * pm[2][2] - pm[1][2] * pm[1][2], adj11 = pm[0][0] * pm[2][2] - pm[0][2] * pm[0][2];
  const float adj01 = pm[0][2] * pm[1][2] - pm[0][1] * pm[2][2];
  return adj00 < 0.0f && adj00 * adj11 > adj01 * adj01 && axis_dir.z > 0.0f;
}

float ltc_shape_corrected(vec3 form_factor, const LtcLobe& lobe) {
  // In the frame of n and v: F's direction o carried back by M (up to a positive scale, M^-1's
  // adjugate times the sign of its determinant), the LTC's density there
  // (o.z / pi) |det M^-1| |M o|^3 with M o = m / det, and the lobe's f (n.l) / E.
  const glm::vec4 e = lobe.entry;
  const float det = e.x * e.w - e.y * e.z;
  const float f_len = glm::length(form_factor);
  const vec3 o = form_factor / f_len;
  const vec3 m = vec3(e.w * o.x - e.y * o.z, det * o.y, e.x * o.z - e.z * o.x);
  const float m_len = glm::length(m);
  const vec3 l = m * ((det < 0.0f ? -1.0f : 1.0f) / m_len);
  const float ltc = o.z / kAreaLightPi * m_len * m_len * m_len / (det * det);
  const float n_dot_v = std::max(lobe.view.z, 1e-4f);
  const vec3 h = glm::normalize(l + lobe.view);
  const float lobe_value =
      l.z > 0.0f ? float(ggx_specular_brdf(n_dot_v, l.z, h.z, lobe.alpha)) * l.z / lobe.albedo : 0.0f;
  const float ratio = ltc > 0.0f && std::isfinite(lobe_value / ltc) ? lobe_value / ltc : 1.0f;
  const float weight = std::exp(-5.0f * f_len);
  return form_factor.z * (weight * ratio + (1.0f - weight));
}

namespace {

// A capsule with ends a and b (a = b for a sphere). Seen from within its cylinder's reach
// (closer to the axis line than r, beyond an end), no plane through the point touches the
// cylinder, and the nearer end's sphere hides the rest: its cone is the capsule's (tubes seen
// nearly end on read 12 to 16% low as two half circles joined). A sphere (`may_cone`: the sphere
// lights) wholly above the surface's horizon whose elliptical cone is wholly above the cosine's
// is that cone, exactly; anything else the outline polygon, clipped. (The round cone of the same
// vector form factor clipped to the cosine's horizon, Heitz and Hill's approximation, read up to
// 11% high there.) A tube seen end on takes the round polygon of its nearer end: the cone gave
// the same errors on five sets of 1,200 points to the fourth digit, and lavapipe runs a branch's
// both sides, so the cone's eigenvalue cost every pixel a tube lights.
float capsule_specular(vec3 a, vec3 b, float radius, vec3 n, vec3 v, const LtcLobe& lobe, bool may_cone) {
  const vec3 axis = b - a;
  const float len = glm::length(axis);
  const vec3 dir = len > 0.0f ? axis / len : vec3(0.0f);
  const bool end_on = !(len > 0.0f) || !(glm::length(a - dir * glm::dot(a, dir)) > radius);
  const vec3 near = glm::dot(a, a) < glm::dot(b, b) ? a : b;
  const bool cone = may_cone && end_on && radius > 0.0f && glm::dot(glm::normalize(n), near) >= radius;
  vec3 f(0.0f);
  const bool exact = cone && ltc_cone_form_factor(near, radius, ltc_to_cosine(n, v, lobe.entry), f);
  if (!exact) f = capsule_form_factor(end_on ? near : a, end_on ? near : b, radius, n, v, lobe.entry);
  return f.z > 0.0f ? ltc_shape_corrected(f, lobe) : 0.0f;
}

}  // namespace

float ltc_sphere_specular(const SphereLight& light, vec3 p, vec3 n, vec3 v, const LtcLobe& lobe) {
  const vec3 c = light.center - p;
  return specular_result(light.radiance, capsule_specular(c, c, light.radius, n, v, lobe, true));
}

float ltc_tube_specular(const TubeLight& light, vec3 p, vec3 n, vec3 v, const LtcLobe& lobe) {
  return specular_result(light.radiance, capsule_specular(light.end0 - p, light.end1 - p, light.radius, n, v, lobe, false));
}

float ltc_rect_specular(const RectLight& light, vec3 p, vec3 n, vec3 v, const LtcLobe& lobe) {
  const vec3 c = light.center - p;
  const vec3 normal = glm::cross(light.half_x, light.half_y);
  // A one-sided light shines on points in front of it only; its plane holds none.
  if (!light.two_sided && !(glm::dot(c, normal) < 0.0f)) return 0.0f;
  LtcPolygon poly = ltc_polygon(n, v, lobe.entry);
  const vec3 corners[4] = {c - light.half_x - light.half_y, c + light.half_x - light.half_y,
                           c + light.half_x + light.half_y, c - light.half_x + light.half_y};
  for (int i = 0; i < 4; ++i) ltc_add_edge(poly, corners[i], corners[(i + 1) % 4]);
  ltc_finish(poly);
  const vec3 f = form_factor(poly);
  return specular_result(light.radiance, f.z > 0.0f ? ltc_shape_corrected(f, lobe) : 0.0f);
}

}  // namespace lg
