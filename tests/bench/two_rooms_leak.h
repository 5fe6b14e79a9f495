// The leak in the two rooms of examples/worlds/two-rooms-sun.json (the sun comes through a hole
// in the west room's ceiling; nothing lights the east room, whose path-traced floor gets no
// indirect light at all): the mean irradiance a method gives the floor each room's camera sees.
// Shared by lumagraph-bench-lpv and lumagraph-bench-gi-methods.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "runtime/scene/world.h"

namespace lg::bench {

struct RoomFloors {
  double east = 0, west = 0;  // mean green irradiance on the floor pixels, W/m^2
  double leak() const { return east / west; }
};

// `irradiance` renders `world` (its camera moved into one room, looking at that room's floor) at
// width x height and returns the method's irradiance, RGBA floats, rows top down.
RoomFloors two_rooms_floors(World world, uint32_t width, uint32_t height,
                            const std::function<std::vector<float>(const World&)>& irradiance);

}  // namespace lg::bench
