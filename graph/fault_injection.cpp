#include "graph/fault_injection.h"

#include <array>
#include <atomic>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>

namespace lg {
namespace {

constexpr std::array<std::string_view, 4> kSiteNames = {"device_allocation", "shader_module", "file_read",
                                                        "file_write"};

struct SiteState {
  std::atomic<uint64_t> nth{0};  // 0: unarmed
  std::atomic<uint64_t> calls{0};
};

std::array<SiteState, kSiteNames.size()> sites;

void arm(SiteState& s, uint64_t nth) {
  s.calls = 0;
  s.nth = nth;
}

// LUMAGRAPH_FAULT=site:n,...; a malformed entry is reported and ignored (a test hook must not
// change how a run without it behaves).
void arm_from_environment() {
  const char* text = std::getenv("LUMAGRAPH_FAULT");
  if (!text) return;
  std::string_view rest = text;
  while (!rest.empty()) {
    const size_t comma = rest.find(',');
    const std::string_view entry = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    const size_t colon = entry.find(':');
    uint64_t nth = 0;
    const auto site = fault_site_named(entry.substr(0, colon));
    const std::string_view count = colon == std::string_view::npos ? std::string_view{} : entry.substr(colon + 1);
    const auto parsed = std::from_chars(count.data(), count.data() + count.size(), nth);
    if (!site || parsed.ec != std::errc{} || parsed.ptr != count.data() + count.size() || nth == 0) {
      std::fprintf(stderr, "LUMAGRAPH_FAULT: ignoring '%.*s'; expected site:n with n >= 1, sites: %s\n",
                   int(entry.size()), entry.data(), "device_allocation, shader_module, file_read, file_write");
      continue;
    }
    arm(sites[size_t(*site)], nth);
  }
}

SiteState& state(FaultSite site) {
  static std::once_flag environment_read;
  std::call_once(environment_read, arm_from_environment);
  return sites[size_t(site)];
}

}  // namespace

std::optional<FaultSite> fault_site_named(std::string_view name) {
  for (size_t i = 0; i < kSiteNames.size(); ++i)
    if (kSiteNames[i] == name) return FaultSite(i);
  return std::nullopt;
}

void arm_fault(FaultSite site, uint64_t nth) {
  arm(state(site), nth);
}

uint64_t fault_site_calls(FaultSite site) {
  return state(site).calls;
}

bool inject_fault(FaultSite site) {
  SiteState& s = state(site);
  const uint64_t nth = s.nth.load(std::memory_order_relaxed);
  if (nth == 0) return false;
  if (s.calls.fetch_add(1) + 1 != nth) return false;
  s.nth = 0;
  return true;
}

}  // namespace lg
