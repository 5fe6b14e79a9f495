// `lumagraph bake --mode prt`: the transfer of every vertex of a scene's draws (prt_bake.h), and
// the merge of the chunks.
#include "cli/prt_bake_command.h"

#include <cstdio>
#include <exception>
#include <optional>

#include "cli/commands.h"
#include "cli/progress_line.h"
#include "nodes/gi/prt/prt_file.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

struct PrtOptions {
  PrtSettings settings;
  uint32_t chunk_index = 0, chunk_count = 1;
  bool chunked = false;
};

std::optional<std::string> read_prt_options(const Args& args, PrtOptions& o) {
  for (const char* other : {"--max-distance", "--falloff", "--resolution", "--graph", "--env"})
    if (args.value(other)) return std::string(other) + " does not apply to --mode prt";
  if (auto transfer = args.value("--transfer")) {
    const std::optional<TransferKind> kind = parse_transfer_kind(*transfer);
    if (!kind) return "--transfer expects unshadowed, shadowed or interreflected; got '" + *transfer + "'";
    o.settings.kind = *kind;
  }
  uint64_t order = uint64_t(o.settings.order), rays = o.settings.rays, bounces = o.settings.bounces;
  if (auto text = args.value("--order"); text && (!parse_unsigned(*text, kPrtMaxOrder, order) || order < kPrtMinOrder))
    return "--order expects 2, 3 or 4; got '" + *text + "'";
  if (auto bad = read_count(args, "--rays", kPrtMaxRays, rays)) return bad;
  if (auto bad = read_count(args, "--bounces", kPrtMaxBounces, bounces)) return bad;
  if (o.settings.kind != TransferKind::interreflected) {
    if (args.value("--bounces")) return "--bounces applies to --transfer interreflected only";
    bounces = 0;
  }
  o.settings.order = int(order), o.settings.rays = uint32_t(rays), o.settings.bounces = uint32_t(bounces);
  if (auto bad = read_seed(args, o.settings.seed)) return bad;
  if (auto bad = read_chunk(args, max_bake_chunks, o.chunk_index, o.chunk_count, o.chunked)) return bad;
  return std::nullopt;
}

int write_prt(const std::string& out, const PrtFile& file) {
  try {
    write_prt_file(out, file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_write;
  }
  std::printf("wrote %s\n", out.c_str());
  return exit_ok;
}

}  // namespace

int prt_bake_command(const Args& args, const std::string& input, const WorldLoadOptions& load_options,
                     const std::string& out) {
  PrtOptions options;
  if (auto bad = read_prt_options(args, options)) return usage_error("bake", *bad);
  std::optional<PathScene> scene;
  PrtFile file;
  try {
    // Transfer is independent of the lights and the environment: the scene's geometry and
    // materials alone.
    scene.emplace(make_scene_view(load_world(input, load_options), 1.0f), PathEnvironment::none());
    file.header =
        make_prt_header(scene->surfaces().mesh(), input, options.settings, options.chunk_index, options.chunk_count);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: %s: error: %s\n", input.c_str(), e.what());
    return exit_invalid;
  }
  const PrtFileHeader& h = file.header;
  if (h.vertices > kPrtMaxVertices) {
    std::fprintf(stderr, "lumagraph bake: %s: error: %llu vertices, more than a PRT bake holds (%llu)\n", input.c_str(),
                 static_cast<unsigned long long>(h.vertices), static_cast<unsigned long long>(kPrtMaxVertices));
    return exit_invalid;
  }
  ProgressLine progress("bake", "vertices", h.range.size());
  file.data = bake_transfer(*scene, h.settings, h.range, [&](uint64_t done) { progress.update(done); });
  progress.finish();
  size_t valid = 0;
  for (float v : file.data.valid) valid += v > 0.0f;
  std::printf(
      "baked %s transfer of order %d for %llu vertices of %s (chunk %u/%u: %llu to %llu of %llu), %u rays each, %u "
      "bounces, in %.2f s; %zu vertices valid\n",
      transfer_kind_name(h.settings.kind), h.settings.order, static_cast<unsigned long long>(h.range.size()),
      input.c_str(), h.chunk_index, h.chunk_count, static_cast<unsigned long long>(h.range.begin),
      static_cast<unsigned long long>(h.range.end), static_cast<unsigned long long>(h.vertices), h.settings.rays,
      h.settings.bounces, progress.seconds(), valid);
  return write_prt(out, file);
}

int prt_merge_command(const std::vector<std::string>& parts, const std::string& out) {
  PrtFile merged;
  try {
    std::vector<PrtFile> files;
    for (const std::string& path : parts) files.push_back(read_prt_file(path));
    merged = merge_prt_parts(files, parts);
  } catch (const BakeFileError& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_invalid;
  }
  if (int status = write_prt(out, merged); status != exit_ok) return status;
  std::printf("merged %zu parts: %llu vertices\n", parts.size(),
              static_cast<unsigned long long>(merged.header.vertices));
  return exit_ok;
}

}  // namespace lg::cli
