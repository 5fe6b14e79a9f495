#include "graph/compiler/barrier.h"

#include <array>

namespace lg {
namespace {

template <size_t N>
std::string flag_names(uint32_t bits, const std::array<std::string_view, N>& names) {
  if (bits == 0) return "NONE";
  std::string out;
  for (size_t k = 0; k < N; ++k)
    if (bits & (1u << k)) out += (out.empty() ? "" : "|") + std::string(names[k]);
  return out;
}

}  // namespace

std::string stage_names(uint32_t stages) {
  static constexpr std::array<std::string_view, 5> names = {"COMPUTE_SHADER", "FRAGMENT_SHADER", "COLOR_ATTACHMENT_OUTPUT",
                                                           "EARLY_FRAGMENT_TESTS", "LATE_FRAGMENT_TESTS"};
  return flag_names(stages, names);
}

std::string access_names(uint32_t access) {
  static constexpr std::array<std::string_view, 8> names = {
      "SHADER_SAMPLED_READ",     "SHADER_STORAGE_READ",           "SHADER_STORAGE_WRITE",
      "COLOR_ATTACHMENT_READ",   "COLOR_ATTACHMENT_WRITE",        "DEPTH_STENCIL_ATTACHMENT_READ",
      "DEPTH_STENCIL_ATTACHMENT_WRITE", "UNIFORM_READ"};
  return flag_names(access, names);
}

std::string_view layout_name(Layout l) {
  constexpr std::string_view names[] = {"UNDEFINED", "GENERAL", "READ_ONLY_OPTIMAL", "ATTACHMENT_OPTIMAL", "-"};
  return names[static_cast<int>(l)];
}

std::string_view barrier_reason_name(BarrierReason r) {
  constexpr std::string_view names[] = {"first use", "alias", "history",         "read after write",
                                        "write after read", "write after write", "layout transition"};
  return names[static_cast<int>(r)];
}

}  // namespace lg
