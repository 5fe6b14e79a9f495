#include "api/static_results_identity.h"

#if defined(__linux__)
#include <elf.h>
#include <link.h>
#endif

#include <cstring>

#include "graph/fnv1a.h"
#include "nodes/common/node_shaders.h"

namespace lg {
namespace {

#if defined(__linux__)
struct BuildIdSearch {
  uintptr_t address;  // of code in the object searched for
  uint64_t hash;
};

bool contains(const dl_phdr_info& object, uintptr_t address) {
  for (int i = 0; i < object.dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = object.dlpi_phdr[i];
    const uintptr_t start = object.dlpi_addr + segment.p_vaddr;
    if (segment.p_type == PT_LOAD && address >= start && address < start + segment.p_memsz) return true;
  }
  return false;
}

// Hashes the NT_GNU_BUILD_ID note of the loaded object that holds the address searched for.
int hash_build_id(dl_phdr_info* object, size_t, void* data) {
  auto& search = *static_cast<BuildIdSearch*>(data);
  if (!contains(*object, search.address)) return 0;
  auto align4 = [](size_t n) { return (n + 3) & ~size_t{3}; };
  for (int i = 0; i < object->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = object->dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    const char* note = reinterpret_cast<const char*>(object->dlpi_addr + segment.p_vaddr);
    const char* end = note + segment.p_memsz;
    while (note + sizeof(ElfW(Nhdr)) <= end) {
      const auto* header = reinterpret_cast<const ElfW(Nhdr)*>(note);
      const char* name = note + sizeof(ElfW(Nhdr));
      const char* desc = name + align4(header->n_namesz);
      if (header->n_type == NT_GNU_BUILD_ID && header->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0)
        search.hash = fnv1a(desc, header->n_descsz, search.hash);
      note = desc + align4(header->n_descsz);
    }
  }
  return 1;
}
#endif

}  // namespace

uint64_t node_code_identity() {
  static const uint64_t identity = [] {  // the same for the whole process: hashed once
    uint64_t hash = fnv1a_basis;
    for (const EmbeddedShader& shader : node_shaders()) {
      hash = fnv1a(shader.path, hash);
      hash = fnv1a(shader.spirv.data(), shader.spirv.size_bytes(), hash);
    }
#if defined(__linux__)
    BuildIdSearch search{reinterpret_cast<uintptr_t>(&node_code_identity), hash};
    dl_iterate_phdr(hash_build_id, &search);
    hash = search.hash;
#endif
    return hash;
  }();
  return identity;
}

std::vector<std::string> static_input_files(const Plan& plan, const Registry& registry) {
  std::vector<std::string> files;
  for (const PlanNode& node : plan.nodes) {
    const NodeSchema* schema = node.is_static ? registry.find(node.type) : nullptr;
    if (!schema) continue;
    for (const ParamSpec& param : schema->params) {
      const JsonValue* value = param.type == ParamType::path ? node.params.find(param.name) : nullptr;
      if (value && value->is_string()) files.push_back(value->as_string());
    }
  }
  return files;
}

}  // namespace lg
