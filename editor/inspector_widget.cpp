#include "editor/inspector_widget.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <vector>

#include "editor/bake_view.h"
#include "editor/env_probe.h"
#include "editor/vertex_bake_view.h"
#include "nodes/occlusion/bake/bake_file.h"

namespace lg {

namespace {

// Radiance to display: exposure from the mean, Reinhard, then gamma 2.2.
unsigned char display(double v, double exposure) {
  const double x = std::max(0.0, v * exposure);
  return static_cast<unsigned char>(std::lround(255 * std::pow(x / (1 + x), 1 / 2.2)));
}

vtkSmartPointer<vtkPolyData> unit_sphere() {
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1);
  source->SetThetaResolution(256);
  source->SetPhiResolution(128);
  source->Update();
  vtkSmartPointer<vtkPolyData> sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  return sphere;
}

Vec3d direction_of(vtkPolyData* sphere, vtkIdType i) {
  double p[3];
  sphere->GetPoint(i, p);
  const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / len, p[1] / len, p[2] / len};
}

}  // namespace

struct InspectorWidget::Vtk {
  QVTKOpenGLNativeWidget* widget = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  std::vector<std::pair<vtkSmartPointer<vtkActor>, vtkSmartPointer<vtkTextActor>>> spheres;

  void add_sphere(vtkPolyData* sphere, const char* caption, vtkLookupTable* lut) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(sphere);
    if (lut) {
      mapper->SetLookupTable(lut);
      mapper->SetScalarRange(lut->GetRange());
      mapper->SetColorModeToMapScalars();
    } else {
      mapper->SetColorModeToDirectScalars();
    }
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    // Radiance is shown as it is, not shaded by a light.
    actor->GetProperty()->SetLighting(false);
    renderer->AddActor(actor);
    vtkNew<vtkTextActor> text;
    text->SetInput(caption);
    text->GetTextProperty()->SetFontSize(18);
    text->GetTextProperty()->SetJustificationToCentered();
    text->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    renderer->AddActor2D(text);
    spheres.emplace_back(actor.Get(), text.Get());
  }

  // The spheres side by side in a wide view, stacked in a tall one (the editor's dock), with
  // a parallel camera sized so that none is clipped.
  void lay_out(double aspect) {
    if (spheres.empty()) return;
    const bool row = aspect >= 1;
    const double step = row ? 2.4 : 2.9, n = double(spheres.size());
    for (size_t i = 0; i < spheres.size(); ++i) {
      const double offset = (double(i) - (n - 1) / 2) * step;
      const double x = row ? offset : 0, y = row ? 0 : -offset;
      spheres[i].first->SetPosition(x, y, 0);
      spheres[i].second->GetPositionCoordinate()->SetValue(x, y - 1.3, 0);
    }
    const double half_w = row ? (n - 1) / 2 * step + 1.3 : 1.6, half_h = row ? 1.7 : (n - 1) / 2 * step + 1.7;
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(0, 0, 10);
    camera->SetViewUp(0, 1, 0);
    // 15% of the width is kept for the colour bar.
    camera->SetParallelScale(std::max(half_h, half_w / (0.85 * aspect)) * 1.05);
    camera->SetWindowCenter(0.12, 0);
    renderer->ResetCameraClippingRange();
  }
};

InspectorWidget::InspectorWidget(QWidget* parent)
    : QWidget(parent),
      vtk_(std::make_unique<Vtk>()),
      slice_bar_(new QWidget(this)),
      slice_caption_(new QLabel(this)),
      summary_(new QLabel(this)) {
  vtk_->widget = new QVTKOpenGLNativeWidget(this);
  vtk_->widget->setRenderWindow(vtk_->window);
  vtk_->window->AddRenderer(vtk_->renderer);
  vtk_->renderer->SetBackground(0.11, 0.12, 0.14);
  summary_->setWordWrap(true);
  summary_->setContentsMargins(6, 0, 6, 2);
  slice_caption_->setContentsMargins(6, 0, 6, 0);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(vtk_->widget, 1);
  layout->addWidget(slice_bar_);
  layout->addWidget(slice_caption_);
  layout->addWidget(summary_);
  // One slider per axis moves that axis's slice of a volume (hidden until one is shown).
  auto* sliders = new QHBoxLayout(slice_bar_);
  sliders->setContentsMargins(6, 2, 6, 0);
  for (int axis = 0; axis < 3; ++axis) {
    sliders->addWidget(new QLabel(tr("%1 slice").arg(QChar("xyz"[axis])), slice_bar_));
    slice_sliders_[axis] = new QSlider(Qt::Horizontal, slice_bar_);
    sliders->addWidget(slice_sliders_[axis], 1);
    connect(slice_sliders_[axis], &QSlider::valueChanged, this,
            [this, axis](int index) { set_volume_slice(axis, index); });
  }
  slice_bar_->hide();
  slice_caption_->hide();
  show_message(tr("Open an environment (.hdr, .exr) to inspect it, or select an env.load node."));
}

InspectorWidget::~InspectorWidget() = default;

QString InspectorWidget::summary() const {
  return summary_->text();
}

void InspectorWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  vtk_->lay_out(double(std::max(1, vtk_->widget->width())) / std::max(1, vtk_->widget->height()));
}

void InspectorWidget::clear_view() {
  vtk_->renderer->RemoveAllViewProps();
  vtk_->spheres.clear();
  volume_.reset();
  vertex_bake_range_.reset();
  slice_bar_->hide();
  slice_caption_->hide();
}

void InspectorWidget::show_message(const QString& text) {
  clear_view();
  summary_->setText(text);
  vtk_->window->Render();
}

void InspectorWidget::show_error(const QString& text) {
  show_message(text);
  // Also in the view itself, where the eye is, not only in the line below it.
  vtkNew<vtkTextActor> error;
  error->SetInput(text.toUtf8().constData());
  error->GetTextProperty()->SetFontSize(18);
  error->GetTextProperty()->SetColor(1.0, 0.45, 0.4);
  error->GetTextProperty()->SetJustificationToCentered();
  error->GetTextProperty()->SetVerticalJustificationToCentered();
  error->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  error->GetPositionCoordinate()->SetValue(0.5, 0.5);
  vtk_->renderer->AddActor2D(error);
  vtk_->window->Render();
  vtk_->widget->update();
}

bool InspectorWidget::open_environment(const QString& path) {
  try {
    show_environment(load_env_probe(path.toStdString()));
    return true;
  } catch (const ImageFileError& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
}

void InspectorWidget::show_environment(const EnvProbe& probe) {
  clear_view();
  const double exposure = probe.mean_luminance > 0 ? 0.6 / probe.mean_luminance : 1;
  vtkSmartPointer<vtkPolyData> env = unit_sphere(), sh = unit_sphere(), error = unit_sphere();
  vtkNew<vtkUnsignedCharArray> env_rgb, sh_rgb;
  vtkNew<vtkFloatArray> err;
  env_rgb->SetNumberOfComponents(3);
  sh_rgb->SetNumberOfComponents(3);
  const vtkIdType n = env->GetNumberOfPoints();
  env_rgb->SetNumberOfTuples(n);
  sh_rgb->SetNumberOfTuples(n);
  err->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const Vec3d d = direction_of(env, i);
    const Vec3d a = sample_equirect(probe.image, d), b = evaluate_sh_l2(probe.sh, d);
    // Where the SH rings below zero it shows its magnitude in blue, not black.
    const bool ringing = luminance(b) < 0;
    for (int c = 0; c < 3; ++c) {
      env_rgb->SetComponent(i, c, display(a[c], exposure));
      sh_rgb->SetComponent(i, c, ringing ? (c == 2 ? display(-luminance(b), exposure) : 0) : display(b[c], exposure));
    }
    const double mean = probe.mean_luminance > 0 ? probe.mean_luminance : 1;
    err->SetValue(i, float(std::abs(luminance(b) - luminance(a)) / mean));
  }
  env->GetPointData()->SetScalars(env_rgb);
  sh->GetPointData()->SetScalars(sh_rgb);
  error->GetPointData()->SetScalars(err);

  // The colour scale ends at the 95th percentile, so one hot spot does not wash out the rest.
  std::vector<float> sorted(err->GetPointer(0), err->GetPointer(0) + n);
  std::nth_element(sorted.begin(), sorted.begin() + n * 95 / 100, sorted.end());
  vtkNew<vtkLookupTable> lut;
  lut->SetRange(0, std::max(1e-3f, sorted[size_t(n * 95 / 100)]));
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  vtk_->add_sphere(env, "environment", nullptr);
  vtk_->add_sphere(sh, "L2 SH (blue: below zero)", nullptr);
  vtk_->add_sphere(error, "error / mean luminance", lut);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetNumberOfLabels(3);
  bar->SetWidth(0.06);
  bar->SetHeight(0.6);
  bar->SetPosition(0.92, 0.2);
  vtk_->renderer->AddActor2D(bar);

  vtk_->lay_out(double(std::max(1, vtk_->widget->width())) / std::max(1, vtk_->widget->height()));
  vtk_->window->Render();
  vtk_->widget->update();

  summary_->setText(tr("%1 — %2x%3 · mean luminance %4 · L2 SH RMS error %5 (%6% of RMS radiance) · SH below zero "
                       "on %7% of the sphere")
                        .arg(QString::fromStdString(probe.path))
                        .arg(probe.image.width)
                        .arg(probe.image.height)
                        .arg(probe.mean_luminance, 0, 'g', 4)
                        .arg(probe.rms_error, 0, 'g', 4)
                        .arg(100 * probe.relative_rms_error, 0, 'f', 1)
                        .arg(100 * probe.negative_fraction, 0, 'f', 1));
}

bool InspectorWidget::open_bake(const QString& path) {
  try {
    show_volume(load_bake_volume(path.toStdString()));
    return true;
  } catch (const BakeFileError& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
}

void InspectorWidget::show_volume(const BakeVolume& volume) {
  clear_view();
  volume_ = std::make_unique<VolumeSlices>(vtk_->renderer, volume);
  const VolumeSliceState state = volume_->state();
  for (int axis = 0; axis < 3; ++axis) {
    const QSignalBlocker quiet(slice_sliders_[axis]);
    slice_sliders_[axis]->setRange(0, state.dims[axis] - 1);
    slice_sliders_[axis]->setValue(state.slice[axis]);
  }
  slice_bar_->show();
  slice_caption_->setText(QString::fromStdString(volume_->slice_caption()));
  slice_caption_->show();
  summary_->setText(tr("%1 — volume bake, %2 x %3 x %4 points · k_A %5 to %6 over valid points · %7 points inside "
                       "geometry (grey)")
                        .arg(QString::fromStdString(volume.path))
                        .arg(state.dims[0])
                        .arg(state.dims[1])
                        .arg(state.dims[2])
                        .arg(volume.visibility_range[0], 0, 'g', 4)
                        .arg(volume.visibility_range[1], 0, 'g', 4)
                        .arg(volume.invalid_points));
  vtk_->window->Render();
  vtk_->widget->update();
}

std::optional<VolumeSliceState> InspectorWidget::volume_state() const {
  if (!volume_) return std::nullopt;
  return volume_->state();
}

void InspectorWidget::set_volume_slice(int axis, int index) {
  if (!volume_) return;
  volume_->set_slice(axis, index);
  {
    const QSignalBlocker quiet(slice_sliders_[axis]);
    slice_sliders_[axis]->setValue(volume_->state().slice[axis]);
  }
  slice_caption_->setText(QString::fromStdString(volume_->slice_caption()));
  vtk_->window->Render();
  vtk_->widget->update();
}

bool InspectorWidget::open_vertex_bake(const QString& path, const QString& mesh_path) {
  try {
    show_vertex_bake(load_vertex_bake(path.toStdString(), mesh_path.toStdString()));
    return true;
  } catch (const BakeFileError& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
}

void InspectorWidget::show_vertex_bake(const VertexBake& bake) {
  clear_view();
  add_vertex_bake(vtk_->renderer, bake);
  vertex_bake_range_ = bake.visibility_range;
  summary_->setText(tr("%1 on %2 — vertex bake, %3 vertices · k_A %4 to %5 · %6 vertices with nothing baked (grey)")
                        .arg(QString::fromStdString(bake.path))
                        .arg(QString::fromStdString(bake.mesh_path))
                        .arg(bake.mesh->GetNumberOfPoints())
                        .arg(bake.visibility_range[0], 0, 'g', 4)
                        .arg(bake.visibility_range[1], 0, 'g', 4)
                        .arg(bake.invalid_points));
  vtk_->window->Render();
  vtk_->widget->update();
}

std::optional<std::array<double, 2>> InspectorWidget::vertex_bake_range() const {
  return vertex_bake_range_;
}

}  // namespace lg
