#include "nodes/builtin_kernels.h"

#include "nodes/env/brdf_lut/brdf_lut_kernel.h"
#include "nodes/env/irradiance/irradiance_kernel.h"
#include "nodes/env/load/env_load_kernel.h"
#include "nodes/env/sh_project/sh_project_kernel.h"
#include "nodes/env/sky/sky_kernel.h"
#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "nodes/gi/irradiance_volume/irradiance_volume_kernel.h"
#include "nodes/gi/lpv/lpv_kernel.h"
#include "nodes/gi/planar_reflection/planar_reflection_kernel.h"
#include "nodes/gi/prt/prt_kernel.h"
#include "nodes/gi/reflection_capture/reflection_capture_kernel.h"
#include "nodes/gi/voxel/voxel_kernel.h"
#include "nodes/lighting/deferred/deferred_kernel.h"
#include "nodes/lighting/ibl/ibl_kernel.h"
#include "nodes/lighting/ssr/ssr_kernel.h"
#include "nodes/occlusion/bake/bake_kernel.h"
#include "nodes/occlusion/baked/baked_kernel.h"
#include "nodes/occlusion/gtao/gtao_kernel.h"
#include "nodes/occlusion/ssao/ssao_kernel.h"
#include "nodes/post/bilateral/bilateral_kernel.h"
#include "nodes/post/bloom/bloom_kernel.h"
#include "nodes/post/dof/dof_kernel.h"
#include "nodes/post/exposure/exposure_kernel.h"
#include "nodes/post/flare/flare_kernel.h"
#include "nodes/post/taa/taa_kernel.h"
#include "nodes/post/tonemap/tonemap_kernel.h"
#include "nodes/post/upsample/upsample_kernel.h"
#include "nodes/scene/forward_transparent/forward_transparent_kernel.h"
#include "nodes/scene/gbuffer/gbuffer_kernel.h"

namespace lg {

const KernelRegistry& builtin_kernels() {
  static const KernelRegistry registry = [] {
    KernelRegistry r;
    r.add("scene.gbuffer", make_gbuffer_kernel);
    r.add("env.brdf_lut", make_brdf_lut_kernel);
    r.add("env.irradiance", make_irradiance_kernel);
    r.add("env.load", make_env_load_kernel);
    r.add("env.sh_project", make_sh_project_kernel);
    r.add("env.sky", make_sky_kernel);
    r.add("env.specular_prefilter", make_specular_prefilter_kernel);
    r.add("gi.irradiance_volume", make_irradiance_volume_kernel);
    r.add("gi.lpv", make_lpv_kernel);
    r.add("gi.planar_reflection", make_planar_reflection_kernel);
    r.add("gi.prt", make_prt_kernel);
    r.add("gi.reflection_capture", make_reflection_capture_kernel);
    r.add("gi.voxel", make_voxel_kernel);
    r.add("lighting.deferred", make_deferred_kernel);
    r.add("lighting.ibl", make_ibl_kernel);
    r.add("lighting.ssr", make_ssr_kernel);
    r.add("occlusion.bake", make_bake_kernel);
    r.add("occlusion.baked", make_baked_kernel);
    r.add("occlusion.gtao", make_gtao_kernel);
    r.add("occlusion.ssao", make_ssao_kernel);
    r.add("post.bilateral", make_bilateral_kernel);
    r.add("post.bloom", make_bloom_kernel);
    r.add("post.dof", make_dof_kernel);
    r.add("post.exposure", make_exposure_kernel);
    r.add("post.flare", make_flare_kernel);
    r.add("post.taa", make_taa_kernel);
    r.add("post.tonemap", make_tonemap_kernel);
    r.add("post.upsample", make_upsample_kernel);
    r.add("scene.forward_transparent", make_forward_transparent_kernel);
    return r;
  }();
  return registry;
}

}  // namespace lg
