// What the plan's resources become on the GPU: the image or buffer description of a lowered
// resource (kind, format, extent, mips, layers), for Image::placed and Buffer::placed, and the
// device's memory needs of each, for the compiler's alias phase.
#pragma once

#include "graph/compiler/alias.h"
#include "graph/compiler/lowered_graph.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"

namespace lg {

class Context;

// Throws GpuError for a buffer resource or an unknown format. A 3D texture takes its depth
// from `layers`, as the compiler sizes it (width x height x layers texels).
ImageDesc image_desc(const LoweredResource& resource);
// Throws GpuError for an image resource.
BufferDesc buffer_desc(const LoweredResource& resource);

// The bytes and alignment the device needs for `resource` (drivers pad images beyond
// width x height x texel size). Throws GpuError for an unknown format.
ResourceMemory device_memory_needs(const Context& context, const LoweredResource& resource);

// Alias options whose placements hold each resource as `context`'s device lays it out.
// The context must outlive the options.
AliasOptions device_alias_options(const Context& context);

}  // namespace lg
