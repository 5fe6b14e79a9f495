#include "runtime/exec/static_results_file.h"

#include "graph/fnv1a.h"
#include "runtime/gpu/byte_stream.h"

namespace lg {
namespace {

constexpr char magic[8] = {'L', 'G', 'S', 'T', 'A', 'T', 'I', 'C'};
constexpr uint32_t format_version = 1;
// magic, version, device identity, key, payload size, payload checksum.
constexpr size_t header_bytes = sizeof magic + 4 + device_identity_bytes + 8 + 8 + 8;

}  // namespace

uint64_t static_results_key(const Plan& plan, const StaticResultsIdentity& identity) {
  ByteWriter key;
  bool any = false;
  for (const PlanPass& pass : plan.passes) {
    if (!pass.is_static) continue;
    any = true;
    key.put_bytes(pass.name.data(), pass.name.size() + 1);  // with its terminator: names stay apart
    key.put(pass.cache_key);
  }
  if (!any) return 0;
  for (const PlanResource& r : plan.resources) {
    if (!is_static_result(r)) continue;
    const LoweredResource& d = r.desc;
    key.put_bytes(d.name.data(), d.name.size() + 1);
    key.put_bytes(d.format.data(), d.format.size() + 1);
    key.put(d.kind);
    key.put(d.width), key.put(d.height), key.put(d.layers), key.put(d.mips), key.put(d.bytes);
  }
  put_device_identity(key, identity.device);
  key.put(identity.code);
  key.put(identity.inputs);
  const uint64_t hash = fnv1a(as_byte_span(key.take()));
  return hash ? hash : 1;  // 0 means "nothing to store"
}

std::string static_results_file_name(uint64_t key) {
  return "static-results-" + hex_digits(key, 16) + ".bin";
}

std::string encode_static_results(const DeviceIdentity& device, uint64_t key, std::span<const StoredResult> results) {
  ByteWriter payload;
  payload.put(static_cast<uint32_t>(results.size()));
  for (const StoredResult& r : results) {
    payload.put(static_cast<uint32_t>(r.name.size()));
    payload.put_bytes(r.name.data(), r.name.size());
    payload.put(static_cast<uint64_t>(r.bytes.size()));
    payload.put_bytes(r.bytes.data(), r.bytes.size());
  }
  const std::string body = payload.take();
  ByteWriter out;
  out.put_bytes(magic, sizeof magic);
  out.put(format_version);
  put_device_identity(out, device);
  out.put(key);
  out.put(static_cast<uint64_t>(body.size()));
  out.put(fnv1a(as_byte_span(body)));
  out.put_bytes(body.data(), body.size());
  return out.take();
}

DecodedStaticResults decode_static_results(std::string_view file, const DeviceIdentity& device, uint64_t key) {
  auto refuse = [](std::string why) { return DecodedStaticResults{{}, std::move(why)}; };
  if (file.size() < header_bytes)
    return refuse("truncated: " + std::to_string(file.size()) + " bytes, shorter than the " +
                  std::to_string(header_bytes) + "-byte header");
  ByteReader in(file);
  if (in.get_bytes(sizeof magic) != std::string_view(magic, sizeof magic))
    return refuse("not a Lumagraph static results file (wrong magic)");
  if (const auto version = in.get<uint32_t>(); version != format_version)
    return refuse("format version " + std::to_string(version) + ", this build reads " + std::to_string(format_version));
  if (const DeviceIdentity made_on = get_device_identity(in); !(made_on == device))
    return refuse("made on another device or driver (" + describe_device(made_on) + "; this is " +
                  describe_device(device) + ")");
  if (const auto made_for = in.get<uint64_t>(); made_for != key)
    return refuse("made for another key (" + hex_digits(made_for, 16) + ", not " + hex_digits(key, 16) + ")");
  const auto payload_size = in.get<uint64_t>();
  const auto checksum = in.get<uint64_t>();
  if (payload_size != in.left())
    return refuse("truncated or padded: the header promises " + std::to_string(payload_size) +
                  " bytes of results, the file holds " + std::to_string(in.left()));
  if (fnv1a(as_byte_span(file.substr(header_bytes))) != checksum)
    return refuse("corrupt: the results' checksum does not match");
  // The checksum held, so what follows was written by encode_static_results; the bounds are
  // checked anyway, as a file of the right checksum and a wrong layout costs nothing to refuse.
  auto malformed = [&] { return refuse("corrupt: the results run past the end of the file"); };
  if (in.left() < 4) return malformed();
  DecodedStaticResults out;
  for (auto count = in.get<uint32_t>(); count > 0; --count) {
    if (in.left() < 4) return malformed();
    const auto name_size = in.get<uint32_t>();
    if (in.left() < name_size + 8ull) return malformed();
    StoredResult& r = out.results.emplace_back();
    r.name = in.get_bytes(name_size);
    const auto size = in.get<uint64_t>();
    if (in.left() < size) return malformed();
    const auto bytes = as_byte_span(in.get_bytes(size));
    r.bytes.assign(bytes.begin(), bytes.end());
  }
  if (in.left() != 0) return refuse("corrupt: " + std::to_string(in.left()) + " bytes after the last result");
  return out;
}

}  // namespace lg
