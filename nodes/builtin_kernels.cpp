#include "nodes/builtin_kernels.h"

#include "nodes/lighting/deferred/deferred_kernel.h"
#include "nodes/occlusion/gtao/gtao_kernel.h"
#include "nodes/occlusion/ssao/ssao_kernel.h"
#include "nodes/post/tonemap/tonemap_kernel.h"
#include "nodes/scene/gbuffer/gbuffer_kernel.h"

namespace lg {

const KernelRegistry& builtin_kernels() {
  static const KernelRegistry registry = [] {
    KernelRegistry r;
    r.add("scene.gbuffer", make_gbuffer_kernel);
    r.add("lighting.deferred", make_deferred_kernel);
    r.add("occlusion.gtao", make_gtao_kernel);
    r.add("occlusion.ssao", make_ssao_kernel);
    r.add("post.tonemap", make_tonemap_kernel);
    return r;
  }();
  return registry;
}

}  // namespace lg
