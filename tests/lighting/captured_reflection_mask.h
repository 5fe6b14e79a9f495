// Which pixels' reflections a reflection probe can hold: the pixels whose reflection lobe meets
// only what the probes capture. An entity with `captured_by_probes: false` (a ball inside a room's
// proxy) is missing from every probe's cube, so a floor pixel that mirrors it is wrong under any
// probe lookup, with or without parallax; where such an object shows the lamp's highlight, those
// few pixels dominate an RMS error and hide what parallax does to the rest. The benchmark reports
// the error over this mask beside the whole floor's.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/scene/world.h"

namespace lg::test {

// One byte per pixel of `world`'s camera at width x height: 1 where the camera's first hit is a
// surface whose mirror reflection, and the 8 directions around it tilted by 4 alpha radians (the
// GGX lobe of perceptual roughness sqrt(alpha), out to where little of its energy is left), meet
// no entity left out of the captures (or nothing: the sky counts as captured); 0 elsewhere and
// where the camera sees nothing. Geometric normals: right for the flat floors it is used on.
std::vector<uint8_t> captured_reflection_mask(const World& world, uint32_t width, uint32_t height, float alpha);

}  // namespace lg::test
