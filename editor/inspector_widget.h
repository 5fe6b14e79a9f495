// The inspector's 3D view (VTK): an environment on a sphere beside its L2 SH reconstruction and
// the error between them, with the numbers; a baked occlusion volume as three slices with
// sliders that move them; or a probe bake's volume (probe_view.h), read from a file or live from
// the editor's preview, with a chooser of the bake's volumes, a slider for its slice and, beside
// the view, the octahedral maps of the probe last clicked; or a PRT bake on its mesh (prt_view.h);
// or a node's dumped 3D texture (dumped_volume_view.h: gi.lpv's grid, gi.voxel's voxels) as
// slices and a volume rendering, with choosers of its channel and mip. VTK stays behind this
// header, out of the editor's files.
#pragma once

#include <QString>
#include <QWidget>
#include <array>
#include <memory>
#include <optional>
#include <string>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QVBoxLayout;

namespace lg {

struct EnvProbe;
struct BakeVolume;
struct VolumeSliceState;
struct VertexBake;
struct ProbeBake;
struct ProbeViewState;
struct PrtBake;
struct PrtViewState;
class VolumeSlices;
class DumpedVolumeView;
struct DumpedVolume;
struct DumpedVolumeState;
enum class VolumeChannel;
class ProbeView;
class PrtView;

// Where shown probes come from: a bake file, or the editor's preview (live: the view offers to
// save them, save_probes_requested()).
struct ProbeSource {
  bool live = false;
  QString note;  // added to the summary (a live volume's mode and updates)
};

class InspectorWidget : public QWidget {
  Q_OBJECT
 public:
  explicit InspectorWidget(QWidget* parent = nullptr);
  ~InspectorWidget() override;

  void show_environment(const EnvProbe& probe);
  // Loads and shows a file; on failure the view says why and returns false.
  bool open_environment(const QString& path);

  void show_volume(const BakeVolume& volume);
  // A volume bake (NAME.vti or NAME.lgbake); on failure the view says why and returns false.
  bool open_bake(const QString& path);
  // The shown volume's slices; nullopt when no volume is shown.
  std::optional<VolumeSliceState> volume_state() const;
  void set_volume_slice(int axis, int index);

  // A 3D texture of `lumagraph render --dump` (NAME.vti or NAME.mipK.vti), showing `channel`; on
  // failure the view says why and returns false.
  bool open_dumped_volume(const QString& path, VolumeChannel channel);
  std::optional<DumpedVolumeState> dumped_volume_state() const;
  // Shows another channel or mip of the shown dumped volume (the choosers do it); the slices
  // stay where they are (clamped to a coarser mip's grid). A channel comes from the volume in
  // memory: the file is not read again.
  void set_dumped_volume_channel(VolumeChannel channel);
  void set_dumped_volume_mip(int mip);

  void show_vertex_bake(const VertexBake& bake);
  // A vertex bake (NAME.lgbake) on the mesh or scene it was baked from.
  bool open_vertex_bake(const QString& path, const QString& mesh_path);
  // The shown vertex bake's colour range; nullopt when none is shown.
  std::optional<std::array<double, 2>> vertex_bake_range() const;
  // A PRT bake (NAME.lgprt) on the mesh or scene it was baked from; on failure the view says why
  // and returns false.
  bool open_prt_bake(const QString& path, const QString& mesh_path);
  // Shows the vertex's transfer function on a sphere beside it (a click on the mesh does it).
  void select_prt_vertex(size_t vertex);
  // Selects the vertex nearest the mesh point under display point (x, y); false when the mesh is not there.
  bool select_prt_vertex_at(int x, int y);
  // The shown PRT bake; nullopt when none is shown.
  std::optional<PrtViewState> prt_state() const;
  // Where a vertex of the shown PRT bake is on the 3D view (VTK's display coordinates).
  std::optional<std::array<double, 2>> prt_vertex_display_point(size_t vertex) const;
  // Volume `volume` (from 0) of a probe bake (NAME.lgprobes); on failure the view says why and
  // returns false.
  bool open_probes(const QString& path, int volume = 0);
  // Probes in memory: volume `volume` (from 0) of `bake`, named by its path. Showing again what is
  // shown (the same path, volume and probe counts: a live volume's refresh) keeps the camera, the
  // slice, the selected probe and the exposure. For a volume the bake lacks the view says why
  // and returns false.
  bool show_probes(std::unique_ptr<ProbeBake> bake, int volume, const ProbeSource& source = {});
  // The bake whose probes are shown, or null.
  const ProbeBake* probe_bake() const { return probe_bake_.get(); }
  // Shows another volume of the shown bake (the chooser above the slice does it).
  void set_probe_volume(int volume);
  // The shown probes; nullopt when none are shown.
  std::optional<ProbeViewState> probe_state() const;
  void set_probe_slice(int step);
  // Outlines the probe and shows its maps beside the view.
  void select_probe(size_t probe);
  // Selects the probe under display point (x, y) of the 3D view (VTK's: origin bottom left), as a
  // click there does; false when no probe is there.
  bool select_probe_at(int x, int y);
  // Where a probe's centre is on the 3D view (VTK's display coordinates).
  std::optional<std::array<double, 2>> probe_display_point(size_t probe) const;

  void show_message(const QString& text);
  // A message that something failed: below the view and in red in it.
  void show_error(const QString& text);
  QString summary() const;

 signals:
  // The Save probes button of a live view was pressed.
  void save_probes_requested();

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Vtk;
  void clear_view();
  // The dumped volume at `path`; null, the view saying why, when it cannot be read.
  std::unique_ptr<DumpedVolume> read_dumped_volume(const std::string& path);
  // Shows a loaded dumped volume (kept as dumped_), its slices at `slice` (clamped) or through
  // its content, drawn once.
  void show_dumped_volume(std::unique_ptr<DumpedVolume> volume, VolumeChannel channel,
                          std::optional<std::array<int, 3>> slice);

  std::unique_ptr<Vtk> vtk_;
  void build_probe_panel(QVBoxLayout* panel);

  std::unique_ptr<VolumeSlices> volume_;
  std::unique_ptr<DumpedVolume> dumped_;
  std::unique_ptr<DumpedVolumeView> dumped_view_;
  std::unique_ptr<ProbeBake> probe_bake_;
  std::unique_ptr<ProbeView> probes_;
  std::unique_ptr<PrtBake> prt_bake_;
  std::unique_ptr<PrtView> prt_;
  ProbeSource probe_source_;
  std::optional<std::array<double, 2>> vertex_bake_range_;
  QWidget* slice_bar_;
  std::array<QSlider*, 3> slice_sliders_{};
  QComboBox *dumped_channel_, *dumped_mip_;  // in the slice bar, for a dumped volume only
  QLabel* slice_caption_;
  QWidget* probe_panel_;
  QComboBox* probe_volume_;
  QPushButton* save_probes_;
  QSlider* probe_slice_;
  QLabel *probe_slice_caption_, *probe_caption_, *irradiance_map_, *distance_caption_, *distance_map_;
  QLabel* summary_;
};

}  // namespace lg
