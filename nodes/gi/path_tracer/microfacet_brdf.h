// The BRDF every lighting node shades with (nodes/common/shaders/brdf.glsl: Lambert diffuse plus
// GGX with height-correlated Smith visibility and Schlick Fresnel, alpha = roughness^2 clamped
// to 1e-3, the specular with multiple-scattering compensation and the diffuse weighted by what
// the specular leaves at the view, from nodes/env/brdf_lut/brdf_albedo.h's table as the GLSL
// reads it) on the CPU in double precision, with what a path tracer needs besides its value:
// cosine sampling of the diffuse lobe, sampling of GGX's visible normals for the specular lobe
// (Heitz 2018, "Sampling the GGX Distribution of Visible Normals") and both densities.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "nodes/raytrace/surface_material.h"

namespace lg {

struct BrdfSurface {
  glm::dvec3 normal;         // unit shading normal
  glm::dvec3 diffuse_color;  // base colour x (1 - metalness), before the specular's share
  glm::dvec3 f0;             // specular reflectance at normal incidence
  double roughness = 0.5;    // perceptual: where the albedo table is read
  double alpha = 0.25;
};

BrdfSurface make_brdf_surface(glm::dvec3 normal, const SurfaceMaterial& material);

// Each lobe's BRDF times n.l for unit view v and light l (both pointing away from the surface).
struct BrdfCosine {
  glm::dvec3 diffuse{0.0}, specular{0.0};
  glm::dvec3 sum() const { return diffuse + specular; }
};
BrdfCosine evaluate_brdf(const BrdfSurface& s, glm::dvec3 v, glm::dvec3 l);

// The diffuse lobe's albedo toward v: the diffuse colour times 1 minus the specular albedo there.
glm::dvec3 diffuse_reflectance(const BrdfSurface& s, glm::dvec3 v);

// The probability of sampling the specular lobe (else the diffuse one): by each lobe's share of
// the reflected energy at this view, Fresnel against the diffuse colour.
double specular_lobe_probability(const BrdfSurface& s, glm::dvec3 v);

// A light direction drawn from the lobe for a point u of [0, 1)^2; may fall below the surface.
glm::dvec3 sample_diffuse(const BrdfSurface& s, glm::dvec2 u);
glm::dvec3 sample_specular(const BrdfSurface& s, glm::dvec3 v, glm::dvec2 u);

// The solid-angle density of each sampler for direction l; the mixture's with lobe probability
// p_spec is p_spec specular_pdf + (1 - p_spec) diffuse_pdf.
double diffuse_pdf(const BrdfSurface& s, glm::dvec3 l);
double specular_pdf(const BrdfSurface& s, glm::dvec3 v, glm::dvec3 l);

}  // namespace lg
