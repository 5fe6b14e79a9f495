#include "runtime/gpu/pipeline_cache_store.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

#include "graph/fnv1a.h"
#include "graph/json_writer.h"
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
  std::error_code error;
  if (!std::filesystem::exists(path_, error)) return;  // the first run on this device
  auto ignored = [&](const std::string& why) { warnings_.push_back("pipeline cache " + path_ + " ignored: " + why); };
  if (!std::filesystem::is_regular_file(path_, error)) return ignored("it is not a regular file");
  std::ifstream in(path_, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.is_open() || in.bad()) return ignored(std::string("cannot read it: ") + std::strerror(errno));
  DecodedPipelineCache decoded = decode_pipeline_cache(bytes, device_identity(context_.properties()));
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
    std::error_code made;
    std::filesystem::create_directories(folder_, made);
    if (made)
      error = "cannot make the folder " + folder_ + ": " + made.message();
    else if (!write_file_atomically(path_, encode_pipeline_cache(device_identity(context_.properties()), data), &error))
      error = error.empty() ? "cannot write it" : error;
    else
      file_data_hash_ = hash;
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
