// Real-time diffuse irradiance from sphere, tube (capsule) and rectangle lights: closed forms in
// float math, written to be ported line by line to GLSL (no std:: containers, no recursion).
//
// Each returns the irradiance E (radiance x projected solid angle) at point p with unit normal
// n, clipped to the hemisphere of n and counting only the part of the light p can see. All are
// exact up to float rounding (README.md has the measured errors). Degenerate input returns a
// finite value: 0 for a light of zero size, zero or non-finite radiance, a zero or NaN normal,
// or any NaN/Inf result; p on or inside a sphere or capsule gets the limit of p touching it.
#pragma once

#include <glm/vec3.hpp>

#include "nodes/lighting/deferred/area_light.h"

namespace lg {

// Snyder's horizon-clipped sphere form factor (also Lagarde & de Rousiers 2014).
float sphere_irradiance(const SphereLight& light, glm::vec3 p, glm::vec3 n);
// The capsule's silhouette (two generator lines, two circle arcs) clipped to the horizon and
// integrated with Stokes' theorem (the Lambert edge formula extended to circle arcs).
float tube_irradiance(const TubeLight& light, glm::vec3 p, glm::vec3 n);
// The Lambert polygon formula on the rectangle clipped to the horizon.
float rect_irradiance(const RectLight& light, glm::vec3 p, glm::vec3 n);

// The sphere's projected solid angle (sr), given cos of the angle between n and the direction
// to its center and sin^2 of its angular radius (clamped to 1: p touching the sphere).
float sphere_form_factor(float cos_w, float sin2_a);

}  // namespace lg
