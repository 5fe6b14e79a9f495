// The inspector's 3D view (VTK): an environment on a sphere beside its L2 SH reconstruction and
// the error between them, with the numbers. Probe grids and volumes come later as further
// show_*() calls on the same view; VTK stays behind this header, out of the editor's files.
#pragma once

#include <QWidget>
#include <memory>

class QLabel;

namespace lg {

struct EnvProbe;

class InspectorWidget : public QWidget {
  Q_OBJECT
 public:
  explicit InspectorWidget(QWidget* parent = nullptr);
  ~InspectorWidget() override;

  void show_environment(const EnvProbe& probe);
  // Loads and shows a file; on failure the view says why and returns false.
  bool open_environment(const QString& path);
  void show_message(const QString& text);
  QString summary() const;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Vtk;
  std::unique_ptr<Vtk> vtk_;
  QLabel* summary_;
};

}  // namespace lg
