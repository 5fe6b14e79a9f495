#include "editor/inspector_widget.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <vector>

#include "editor/bake_legend.h"
#include "editor/bake_view.h"
#include "editor/dumped_volume_view.h"
#include "editor/env_probe.h"
#include "editor/probe_view.h"
#include "editor/prt_view.h"
#include "editor/vertex_bake_view.h"
#include "nodes/occlusion/bake/bake_file.h"

namespace lg {

namespace {

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
  vtkNew<vtkCallbackCommand> on_press, on_release;
  int press[2] = {0, 0};  // where the left button went down: a click releases there

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
      probe_panel_(new QWidget(this)),
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
  auto* view_row = new QHBoxLayout;
  view_row->setSpacing(0);
  view_row->addWidget(vtk_->widget, 1);
  view_row->addWidget(probe_panel_);
  layout->addLayout(view_row, 1);
  layout->addWidget(slice_bar_);
  layout->addWidget(slice_caption_);
  layout->addWidget(summary_);
  // One slider per axis moves that axis's slice of a volume (hidden until one is shown).
  auto* sliders = new QHBoxLayout(slice_bar_);
  sliders->setContentsMargins(6, 2, 6, 0);
  // A dumped volume's channel and mip, before the sliders.
  dumped_channel_ = new QComboBox(slice_bar_);
  for (VolumeChannel c : {VolumeChannel::luminance, VolumeChannel::red, VolumeChannel::green, VolumeChannel::blue,
                          VolumeChannel::alpha})
    dumped_channel_->addItem(QString::fromStdString(channel_name(c) + (channel_is_log(c) ? " (log)" : "")));
  dumped_mip_ = new QComboBox(slice_bar_);
  dumped_channel_->setObjectName(QStringLiteral("dumped_channel"));
  dumped_mip_->setObjectName(QStringLiteral("dumped_mip"));
  sliders->addWidget(dumped_channel_);
  sliders->addWidget(dumped_mip_);
  connect(dumped_channel_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int channel) { set_dumped_volume_channel(VolumeChannel(channel)); });
  connect(dumped_mip_, QOverload<int>::of(&QComboBox::activated), this, [this](int mip) { set_dumped_volume_mip(mip); });
  for (int axis = 0; axis < 3; ++axis) {
    sliders->addWidget(new QLabel(tr("%1 slice").arg(QChar("xyz"[axis])), slice_bar_));
    slice_sliders_[axis] = new QSlider(Qt::Horizontal, slice_bar_);
    sliders->addWidget(slice_sliders_[axis], 1);
    connect(slice_sliders_[axis], &QSlider::valueChanged, this,
            [this, axis](int index) { set_volume_slice(axis, index); });
  }
  slice_bar_->hide();
  slice_caption_->hide();
  build_probe_panel(new QVBoxLayout(probe_panel_));
  // A click (press and release at one point, not a drag that turns the view) picks a probe.
  vtkRenderWindowInteractor* interactor = vtk_->window->GetInteractor();
  vtk_->on_press->SetClientData(this);
  vtk_->on_press->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* self = static_cast<InspectorWidget*>(client);
    static_cast<vtkRenderWindowInteractor*>(caller)->GetEventPosition(self->vtk_->press);
  });
  vtk_->on_release->SetClientData(this);
  vtk_->on_release->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* self = static_cast<InspectorWidget*>(client);
    int at[2];
    static_cast<vtkRenderWindowInteractor*>(caller)->GetEventPosition(at);
    if (std::abs(at[0] - self->vtk_->press[0]) + std::abs(at[1] - self->vtk_->press[1]) > 3) return;
    if (self->probes_) self->select_probe_at(at[0], at[1]);
    if (self->prt_) self->select_prt_vertex_at(at[0], at[1]);
  });
  interactor->AddObserver(vtkCommand::LeftButtonPressEvent, vtk_->on_press);
  interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, vtk_->on_release);
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
  dumped_view_.reset();
  dumped_.reset();
  dumped_channel_->hide();
  dumped_mip_->hide();
  probes_.reset();
  probe_bake_.reset();
  prt_.reset();
  prt_bake_.reset();
  probe_panel_->hide();
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
      env_rgb->SetComponent(i, c, display_byte(a[c], exposure));
      sh_rgb->SetComponent(
          i, c, ringing ? (c == 2 ? display_byte(-luminance(b), exposure) : 0) : display_byte(b[c], exposure));
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
  if (dumped_view_) {
    dumped_view_->set_slice(axis, index);
    const QSignalBlocker quiet(slice_sliders_[axis]);
    slice_sliders_[axis]->setValue(dumped_view_->state().slice[axis]);
    slice_caption_->setText(QString::fromStdString(dumped_view_->caption()));
  } else if (volume_) {
    volume_->set_slice(axis, index);
    const QSignalBlocker quiet(slice_sliders_[axis]);
    slice_sliders_[axis]->setValue(volume_->state().slice[axis]);
    slice_caption_->setText(QString::fromStdString(volume_->slice_caption()));
  } else {
    return;
  }
  vtk_->window->Render();
  vtk_->widget->update();
}

std::unique_ptr<DumpedVolume> InspectorWidget::read_dumped_volume(const std::string& path) {
  try {
    return std::make_unique<DumpedVolume>(load_dumped_volume(path));
  } catch (const std::runtime_error& e) {
    show_error(QString::fromStdString(e.what()));
    return nullptr;
  }
}

bool InspectorWidget::open_dumped_volume(const QString& path, VolumeChannel channel) {
  std::unique_ptr<DumpedVolume> volume = read_dumped_volume(path.toStdString());
  if (!volume) return false;
  show_dumped_volume(std::move(volume), channel, std::nullopt);
  return true;
}

void InspectorWidget::show_dumped_volume(std::unique_ptr<DumpedVolume> volume, VolumeChannel channel,
                                         std::optional<std::array<int, 3>> slice) {
  clear_view();
  dumped_ = std::move(volume);
  dumped_view_ = std::make_unique<DumpedVolumeView>(vtk_->renderer, *dumped_, channel);
  if (slice)
    for (int axis = 0; axis < 3; ++axis) dumped_view_->set_slice(axis, (*slice)[axis]);
  const DumpedVolumeState state = dumped_view_->state();
  for (int axis = 0; axis < 3; ++axis) {
    const QSignalBlocker quiet(slice_sliders_[axis]);
    slice_sliders_[axis]->setRange(0, state.dims[axis] - 1);
    slice_sliders_[axis]->setValue(state.slice[axis]);
  }
  {
    const QSignalBlocker quiet_channel(dumped_channel_), quiet_mip(dumped_mip_);
    dumped_channel_->setCurrentIndex(int(channel));
    dumped_mip_->clear();
    for (size_t mip = 0; mip < dumped_->mips.size(); ++mip) dumped_mip_->addItem(tr("mip %1").arg(mip));
    dumped_mip_->setCurrentIndex(dumped_->mip);
  }
  dumped_channel_->show();
  dumped_mip_->show();
  slice_bar_->show();
  slice_caption_->setText(QString::fromStdString(dumped_view_->caption()));
  slice_caption_->show();
  summary_->setText(tr("%1 — dumped 3D texture, %2 x %3 x %4 texels, mip %5 of %6 · %7 from %8 to %9 · %10 texels lit, "
                       "%11 with alpha 0 on the slices (grey)")
                        .arg(QString::fromStdString(dumped_->path))
                        .arg(state.dims[0])
                        .arg(state.dims[1])
                        .arg(state.dims[2])
                        .arg(dumped_->mip)
                        .arg(dumped_->mips.size())
                        .arg(QString::fromStdString(channel_name(channel)))
                        .arg(state.value_range[0], 0, 'g', 4)
                        .arg(state.value_range[1], 0, 'g', 4)
                        .arg(state.lit_points)
                        .arg(state.masked_points));
  vtk_->window->Render();
  vtk_->widget->update();
}

std::optional<DumpedVolumeState> InspectorWidget::dumped_volume_state() const {
  if (!dumped_view_) return std::nullopt;
  return dumped_view_->state();
}

void InspectorWidget::set_dumped_volume_channel(VolumeChannel channel) {
  if (!dumped_) return;
  const std::array<int, 3> slice = dumped_view_->state().slice;
  show_dumped_volume(std::move(dumped_), channel, slice);
}

void InspectorWidget::set_dumped_volume_mip(int mip) {
  if (!dumped_ || mip < 0 || size_t(mip) >= dumped_->mips.size()) return;
  const DumpedVolumeState before = dumped_view_->state();
  std::unique_ptr<DumpedVolume> volume = read_dumped_volume(dumped_->mips[size_t(mip)]);
  if (!volume) return;
  // The same place in the coarser or finer grid.
  std::array<int, 3> dims, slice;
  volume->image->GetDimensions(dims.data());
  for (int axis = 0; axis < 3; ++axis)
    slice[axis] = int(std::lround(double(before.slice[axis]) * dims[axis] / before.dims[axis]));
  show_dumped_volume(std::move(volume), before.channel, slice);
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

bool InspectorWidget::open_prt_bake(const QString& path, const QString& mesh_path) {
  std::unique_ptr<PrtBake> bake;
  try {
    bake = std::make_unique<PrtBake>(load_prt_bake(path.toStdString(), mesh_path.toStdString()));
  } catch (const BakeFileError& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  clear_view();
  prt_bake_ = std::move(bake);
  prt_ = std::make_unique<PrtView>(vtk_->renderer, *prt_bake_);
  const PrtViewState state = prt_->state();
  const PrtSettings& s = prt_bake_->file.header.settings;
  summary_->setText(tr("%1 on %2 — PRT bake, %3 transfer of order %4, %5 vertices · sky visibility %6 to %7 · %8 "
                       "vertices with nothing baked (grey) · click a vertex for its transfer")
                        .arg(path)
                        .arg(mesh_path)
                        .arg(QString::fromUtf8(transfer_kind_name(s.kind)))
                        .arg(s.order)
                        .arg(state.vertices)
                        .arg(state.sky_visibility[0], 0, 'g', 4)
                        .arg(state.sky_visibility[1], 0, 'g', 4)
                        .arg(state.invalid));
  vtk_->window->Render();
  vtk_->widget->update();
  return true;
}

void InspectorWidget::select_prt_vertex(size_t vertex) {
  if (!prt_) return;
  prt_->select(vertex);
  vtk_->window->Render();
  vtk_->widget->update();
}

bool InspectorWidget::select_prt_vertex_at(int x, int y) {
  if (!prt_) return false;
  const std::optional<size_t> vertex = prt_->pick(x, y);
  if (vertex) select_prt_vertex(*vertex);
  return vertex.has_value();
}

std::optional<PrtViewState> InspectorWidget::prt_state() const {
  if (!prt_) return std::nullopt;
  return prt_->state();
}

std::optional<std::array<double, 2>> InspectorWidget::prt_vertex_display_point(size_t vertex) const {
  if (!prt_ || vertex >= prt_->state().vertices) return std::nullopt;
  return prt_->display_point(vertex);
}

void InspectorWidget::build_probe_panel(QVBoxLayout* panel) {
  panel->setContentsMargins(8, 8, 8, 8);
  // The bake's volumes, when it has more than one; a live one can be saved as a bake file.
  probe_volume_ = new QComboBox(probe_panel_);
  probe_volume_->setObjectName(QStringLiteral("probe_volume"));
  panel->addWidget(probe_volume_);
  save_probes_ = new QPushButton(tr("Save probes…"), probe_panel_);
  save_probes_->setToolTip(tr("Write these probes as a .lgprobes bake, for lumagraph-inspect --bake"));
  panel->addWidget(save_probes_);
  connect(save_probes_, &QPushButton::clicked, this, &InspectorWidget::save_probes_requested);
  connect(probe_volume_, QOverload<int>::of(&QComboBox::activated), this, [this](int v) { set_probe_volume(v); });
  panel->addWidget(new QLabel(tr("Slice of the lookup, height:"), probe_panel_));
  probe_slice_ = new QSlider(Qt::Horizontal, probe_panel_);
  panel->addWidget(probe_slice_);
  probe_slice_caption_ = new QLabel(probe_panel_);
  panel->addWidget(probe_slice_caption_);
  probe_caption_ = new QLabel(tr("Click a probe to see its maps."), probe_panel_);
  probe_caption_->setWordWrap(true);
  panel->addSpacing(12);
  panel->addWidget(probe_caption_);
  irradiance_map_ = new QLabel(probe_panel_);
  distance_caption_ = new QLabel(probe_panel_);
  distance_caption_->setWordWrap(true);
  distance_map_ = new QLabel(probe_panel_);
  panel->addWidget(irradiance_map_);
  panel->addWidget(distance_caption_);
  panel->addWidget(distance_map_);
  panel->addStretch(1);
  probe_panel_->setFixedWidth(230);
  probe_panel_->hide();
  connect(probe_slice_, &QSlider::valueChanged, this, [this](int step) { set_probe_slice(step); });
}

bool InspectorWidget::open_probes(const QString& path, int volume) {
  try {
    return show_probes(std::make_unique<ProbeBake>(load_probe_bake(path.toStdString())), volume);
  } catch (const BakeFileError& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
}

bool InspectorWidget::show_probes(std::unique_ptr<ProbeBake> bake, int volume, const ProbeSource& source) {
  const QString name = QString::fromStdString(bake->path);
  if (volume < 0 || size_t(volume) >= bake->grids.size()) {
    show_error(tr("%1: no volume %2; the bake holds %3").arg(name).arg(volume + 1).arg(bake->grids.size()));
    return false;
  }
  // A refresh of what is shown keeps how it is looked at.
  struct Kept {
    vtkNew<vtkCamera> camera;
    ProbeViewState state;
  };
  std::optional<Kept> kept;
  if (probes_ && probe_bake_ && probe_bake_->path == bake->path) {
    const ProbeViewState shown = probes_->state();
    if (shown.volume == size_t(volume) && shown.counts == bake->grids[size_t(volume)].counts()) {
      kept.emplace();
      kept->camera->DeepCopy(vtk_->renderer->GetActiveCamera());
      kept->state = shown;
    }
  }
  clear_view();
  probe_bake_ = std::move(bake);
  probe_source_ = source;
  probes_ = std::make_unique<ProbeView>(vtk_->renderer, *probe_bake_, size_t(volume),
                                        kept ? std::optional(kept->state.exposure) : std::nullopt);
  if (kept) {
    vtk_->renderer->GetActiveCamera()->DeepCopy(kept->camera);
    vtk_->renderer->ResetCameraClippingRange();
  }
  const ProbeViewState state = probes_->state();
  {
    const QSignalBlocker quiet(probe_slice_);
    probe_slice_->setRange(0, state.slices - 1);
  }
  {
    const QSignalBlocker quiet(probe_volume_);
    probe_volume_->clear();
    for (size_t v = 0; v < state.volumes; ++v) {
      const glm::ivec3 c = probe_bake_->grids[v].counts();
      probe_volume_->addItem(
          tr("Volume %1 of %2: %3 x %4 x %5").arg(v + 1).arg(state.volumes).arg(c.x).arg(c.y).arg(c.z));
    }
    probe_volume_->setCurrentIndex(volume);
  }
  probe_volume_->setVisible(state.volumes > 1);
  save_probes_->setVisible(source.live);
  set_probe_slice(kept ? kept->state.slice : state.slice);
  irradiance_map_->clear();
  distance_caption_->clear();
  distance_map_->clear();
  probe_caption_->setText(tr("Click a probe to see its maps."));
  probe_panel_->show();
  if (kept && kept->state.selected) select_probe(*kept->state.selected);
  const ProbeFileHeader& h = probe_bake_->file.header;
  summary_->setText(tr("%1 — volume %2 of %3, %4 x %5 x %6 probes · %7 on, %8 off · %9 moved · baked from %10 with "
                       "%11 rays, %12 bounces")
                        .arg(name)
                        .arg(volume + 1)
                        .arg(state.volumes)
                        .arg(state.counts.x)
                        .arg(state.counts.y)
                        .arg(state.counts.z)
                        .arg(state.active)
                        .arg(state.probes - state.active)
                        .arg(state.relocated)
                        .arg(QString::fromStdString(h.scene))
                        .arg(h.settings.rays)
                        .arg(h.settings.bounces) +
                    (source.note.isEmpty() ? QString() : QStringLiteral(" · ") + source.note));
  return true;
}

void InspectorWidget::set_probe_volume(int volume) {
  if (!probes_ || volume < 0 || size_t(volume) >= probe_bake_->grids.size()) return;
  show_probes(std::move(probe_bake_), volume, probe_source_);
}

std::optional<ProbeViewState> InspectorWidget::probe_state() const {
  if (!probes_) return std::nullopt;
  return probes_->state();
}

void InspectorWidget::set_probe_slice(int step) {
  if (!probes_) return;
  probes_->set_slice(step);
  const ProbeViewState state = probes_->state();
  {
    const QSignalBlocker quiet(probe_slice_);
    probe_slice_->setValue(state.slice);
  }
  probe_slice_caption_->setText(
      tr("row %1 of %2, %3% covered")
          .arg(state.slice_height + 1, 0, 'g', 3)
          .arg(state.counts.y)
          .arg(100.0 * double(state.slice_covered) / double(std::max<size_t>(1, state.slice_samples)), 0, 'f', 0));
  vtk_->window->Render();
  vtk_->widget->update();
}

void InspectorWidget::select_probe(size_t probe) {
  if (!probes_ || probe >= probes_->state().probes) return;
  probes_->select(probe);
  const ProbeMaps maps = probes_->maps(probe);
  const double exposure = probes_->state().exposure;
  // Stored texels drawn as blocks, nearest, so each texel reads as what it holds.
  constexpr int shown = 168;
  QImage irradiance(kProbeIrradianceTexels, kProbeIrradianceTexels, QImage::Format_RGB888);
  for (int j = 0; j < kProbeIrradianceTexels; ++j)
    for (int i = 0; i < kProbeIrradianceTexels; ++i) {
      const glm::vec3 e = maps.irradiance[size_t(j * kProbeIrradianceTexels + i)];
      irradiance.setPixel(i, j,
                          qRgb(display_byte(e.r, exposure), display_byte(e.g, exposure), display_byte(e.b, exposure)));
    }
  const float far = std::max(1e-6f, *std::max_element(maps.distance.begin(), maps.distance.end()));
  QImage distance(kProbeDistanceTexels, kProbeDistanceTexels, QImage::Format_Grayscale8);
  for (int j = 0; j < kProbeDistanceTexels; ++j)
    for (int i = 0; i < kProbeDistanceTexels; ++i)
      distance.setPixel(i, j, uint(std::lround(255 * maps.distance[size_t(j * kProbeDistanceTexels + i)] / far)));
  irradiance_map_->setPixmap(QPixmap::fromImage(irradiance.scaled(shown, shown)));
  distance_map_->setPixmap(QPixmap::fromImage(distance.scaled(shown, shown)));
  probe_caption_->setText(tr("Probe %1, cell (%2, %3, %4), at (%5, %6, %7), %8\n\nIrradiance, octahedral %9 x %9:")
                              .arg(probe)
                              .arg(maps.cell.x)
                              .arg(maps.cell.y)
                              .arg(maps.cell.z)
                              .arg(maps.position.x, 0, 'f', 2)
                              .arg(maps.position.y, 0, 'f', 2)
                              .arg(maps.position.z, 0, 'f', 2)
                              .arg(maps.active ? tr("on") : tr("off (inside geometry)"))
                              .arg(kProbeIrradianceTexels));
  distance_caption_->setText(
      tr("Mean distance to surfaces, %1 x %1 (black 0, white %2):").arg(kProbeDistanceTexels).arg(far, 0, 'g', 3));
  vtk_->window->Render();
  vtk_->widget->update();
}

bool InspectorWidget::select_probe_at(int x, int y) {
  if (!probes_) return false;
  const std::optional<size_t> probe = probes_->pick(x, y);
  if (probe) select_probe(*probe);
  return probe.has_value();
}

std::optional<std::array<double, 2>> InspectorWidget::probe_display_point(size_t probe) const {
  if (!probes_ || probe >= probes_->state().probes) return std::nullopt;
  return probes_->display_point(probe);
}

}  // namespace lg
