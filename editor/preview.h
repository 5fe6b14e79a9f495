// The seam for the live preview: something that renders one port of a graph to float pixels.
// RuntimePreview does it on the runtime; MainWindow::set_preview plugs one in, and the Preview
// dock (preview_panel.h) shows its pixels after each edit with an exposure and a channel of
// its own, and reads out the pixel under the cursor.
#pragma once

#include <QMetaType>
#include <QSize>
#include <QString>
#include <string>
#include <utility>
#include <vector>

#include "editor/live_probes.h"
#include "graph/graph.h"
#include "graph/scene_summary.h"

namespace lg::editor {

// A port the preview can show (preview_ports.h).
struct PreviewPort {
  std::string name;   // "light.color", "gbuf.gbuffer.normal"; empty: the graph's main output
  PortRef port;       // the node's output port
  int component = 0;  // within a bundle (the G-buffer's components)
};

// What an image's values are, which says how to show them.
enum class PreviewEncoding {
  display,  // sRGB values already (texture2d:ldr): shown as they are
  colour,   // linear light (hdr, decoded sRGB albedo): exposed, then sRGB-encoded
  data,     // normals, depth, occlusion, lookup tables: exposed, shown as values
};

// One image of a port: its own values, before exposure, at the resource's own size.
struct PreviewImage {
  int width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats a pixel, rows top down
  PreviewEncoding encoding = PreviewEncoding::colour;
  int channels = 4;  // of the resource's format: a one-channel image shows as grey
  QString note;      // which part of the resource it is ("face +X"), or empty
  // GPU time of each pass of the frame it came from (pass name, ms; negative when skipped as
  // cached), for the compile view.
  std::vector<std::pair<std::string, double>> pass_ms;
  // The frame's gi.irradiance_volume probes, for the inspector (live_probes.h); empty for a
  // renderer without them.
  LiveProbes probes;

  bool empty() const { return rgba.empty(); }
};

class PreviewRenderer {
 public:
  virtual ~PreviewRenderer() = default;
  // `port` of the graph, rendered on a frame of about `size`; an empty image with `error` set
  // when it cannot (the graph fails, the port is a buffer).
  virtual PreviewImage render(const Graph& graph, QSize size, const PreviewPort& port, QString* error) = 0;
  // The scene it renders, which live validation and the compile view then compile for too, so
  // that what they say is skipped is what the preview skips. Asked on the UI thread.
  virtual SceneSummary scene_summary() const { return default_scene_summary(); }
};

}  // namespace lg::editor

Q_DECLARE_METATYPE(lg::editor::PreviewImage)
