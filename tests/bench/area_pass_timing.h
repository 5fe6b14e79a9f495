// lighting.deferred's area pass GPU time at a frame size, with its area_specular param set
// (apart from area_specular_bench.cpp: the renderer's headers name their own light types).
#pragma once

#include <cstdint>
#include <string>

namespace lg::bench {

// examples/default.json on the embedded default world; the median over `frames` frames after the
// first (which builds the pipelines).
double area_pass_ms(const std::string& area_specular, uint32_t width, uint32_t height, uint32_t frames);

}  // namespace lg::bench
