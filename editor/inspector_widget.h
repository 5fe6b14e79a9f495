// The inspector's 3D view (VTK): an environment on a sphere beside its L2 SH reconstruction and
// the error between them, with the numbers, or a baked occlusion volume as three slices with
// sliders that move them. Probe grids come later as further show_*() calls on the same view;
// VTK stays behind this header, out of the editor's files.
#pragma once

#include <QWidget>
#include <array>
#include <memory>
#include <optional>

class QLabel;
class QSlider;

namespace lg {

struct EnvProbe;
struct BakeVolume;
struct VolumeSliceState;
struct VertexBake;
class VolumeSlices;

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

  void show_vertex_bake(const VertexBake& bake);
  // A vertex bake (NAME.lgbake) on the mesh or scene it was baked from.
  bool open_vertex_bake(const QString& path, const QString& mesh_path);
  // The shown vertex bake's colour range; nullopt when none is shown.
  std::optional<std::array<double, 2>> vertex_bake_range() const;
  void show_message(const QString& text);
  // A message that something failed: below the view and in red in it.
  void show_error(const QString& text);
  QString summary() const;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Vtk;
  void clear_view();

  std::unique_ptr<Vtk> vtk_;
  std::unique_ptr<VolumeSlices> volume_;
  std::optional<std::array<double, 2>> vertex_bake_range_;
  QWidget* slice_bar_;
  std::array<QSlider*, 3> slice_sliders_{};
  QLabel* slice_caption_;
  QLabel* summary_;
};

}  // namespace lg
