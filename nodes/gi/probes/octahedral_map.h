// The octahedral map of directions onto the unit square that probes store their data in
// (Cigolle et al. 2014, as DDGI uses it): the sphere projected onto the octahedron
// |x| + |y| + |z| = 1, its lower half folded out over the corners. A square map of k x k texels
// has texel (i, j) centred at ((i + 0.5) / k, (j + 0.5) / k); a texel one past an edge is the
// mirrored texel of that edge (and past a corner the opposite corner), which is how DDGI fills
// its one-texel borders for seamless bilinear filtering.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lg {

glm::dvec2 octahedral_encode(glm::dvec3 direction);  // unit direction -> [0, 1]^2
glm::dvec3 octahedral_decode(glm::dvec2 uv);         // -> unit direction

// The texel inside a k x k map that texel (i, j), at most one past an edge, stands for.
glm::ivec2 octahedral_wrap(int i, int j, int k);

// Bilinear weights of the four texels around `direction` in a k x k map: texels (as wrapped)
// and weights, for reading a map the way a GPU reads it with its borders.
struct OctahedralTaps {
  glm::ivec2 texel[4];
  double weight[4];
};
OctahedralTaps octahedral_taps(glm::dvec3 direction, int k);

}  // namespace lg
