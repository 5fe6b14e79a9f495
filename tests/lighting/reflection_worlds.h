// The worlds issue 17's reflections (and issue 18's voxel specular cone) are measured on, with the roughness of their metal
// surfaces so that a SurfaceMask (specular_error.h) picks the floor or the ball:
// - the reflection room (examples/worlds/reflection-room.json): a closed room, steel floor, chrome
//   ball, one box probe with the room as its proxy;
// - the gallery (examples/worlds/gallery.json) with its floor polished: the file's floor is a
//   rough dielectric (0.7, beyond lighting.ssr's default max_roughness of 0.5, and a dielectric's
//   specular term cannot be told from its diffuse one in the lit image), so here it is steel at
//   roughness 0.2. Its box probe, 1 m above the floor in front of the plinths, covers the whole
//   floor with the gallery's bounds (floor, back wall, 4 m up) as its proxy;
// - the Cornell box with its floor and tall block metal (polished_cornell_box()).
#pragma once

#include <string>

#include "runtime/scene/world.h"

namespace lg::test {

struct ReflectionWorld {
  std::string name;
  World world;
  float floor_roughness, ball_roughness;
};

ReflectionWorld reflection_room();
ReflectionWorld polished_gallery();
// The Cornell box (examples/worlds/cornell-box.json) with its floor steel at roughness 0.2 and its
// tall block chrome at 0.05 (the "ball" of a SurfaceMask): the file's surfaces are all rough
// dielectrics. Lit by its lamp and by a sun through the open front, for gi.voxel's specular cone.
ReflectionWorld polished_cornell_box();

}  // namespace lg::test
