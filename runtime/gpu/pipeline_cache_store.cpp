#include "runtime/gpu/pipeline_cache_store.h"

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <utility>

#include "graph/fnv1a.h"
#include "runtime/gpu/cache_file_io.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/pipeline_cache_file.h"

namespace lg {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

std::string default_pipeline_cache_folder() {
  if (std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/lumagraph";
  if (std::string home = environment("HOME"); !home.empty()) return home + "/.cache/lumagraph";
  return {};
}

bool pipeline_cache_disabled_by_environment() {
  const std::string value = environment("LUMAGRAPH_PIPELINE_CACHE");
  return value == "off" || value == "0" || value == "false" || value == "no";
}

PipelineCacheStore::PipelineCacheStore(Context& context, const std::string& folder)
    : context_(context),
      folder_(folder),
      path_(folder + "/" + pipeline_cache_file_name(device_identity(context.properties()))) {
  load();
  compiled_at_save_ = compiled();
}

uint64_t PipelineCacheStore::compiled() const {
  const PipelineCache& pipelines = context_.pipelines();
  return pipelines.created() - pipelines.driver_cache_hits();
}

void PipelineCacheStore::load() {
  const CacheFileRead file = read_cache_file(path_);
  if (!file.exists) return;  // the first run on this device
  auto ignored = [&](const std::string& why) { warnings_.push_back("pipeline cache " + path_ + " ignored: " + why); };
  if (!file.problem.empty()) return ignored(file.problem);
  DecodedPipelineCache decoded = decode_pipeline_cache(file.bytes, device_identity(context_.properties()));
  if (!decoded.problem.empty()) return ignored(decoded.problem);
  if (!context_.pipelines().merge(decoded.driver_data)) return ignored("the driver refused its data");
  loaded_bytes_ = decoded.driver_data.size();
  file_data_hash_ = fnv1a(decoded.driver_data);
}

bool PipelineCacheStore::save() {
  if (unwritable_) return false;
  if (compiled() == compiled_at_save_) return true;  // nothing the file lacks
  std::string error;
  try {
    const std::vector<std::byte> data = context_.pipelines().driver_data();
    const uint64_t hash = fnv1a(data);
    if (file_data_hash_ == hash) {  // the file has it all: no write, no fsync
      compiled_at_save_ = compiled();
      return true;
    }
    file_data_hash_.reset();  // until written
    error = write_cache_file(folder_, path_, encode_pipeline_cache(device_identity(context_.properties()), data));
    if (error.empty()) file_data_hash_ = hash;
  } catch (const std::exception& e) {  // vkGetPipelineCacheData failed: the device is lost
    error = e.what();
  }
  if (!error.empty()) {
    unwritable_ = true;
    warnings_.push_back("pipeline cache " + path_ + " not saved (pipelines are built again next run): " + error);
    return false;
  }
  compiled_at_save_ = compiled();
  return true;
}

std::vector<std::string> PipelineCacheStore::take_warnings() {
  return std::exchange(warnings_, {});
}

}  // namespace lg
