#include "editor/param_widgets.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>
#include <cmath>
#include <limits>

namespace lg::editor {

namespace {

QString text_of(const std::string& s) {
  return QString::fromStdString(s);
}

bool is_integer_type(ParamType t) {
  return t == ParamType::int_ || t == ParamType::int2;
}

JsonValue number_value(const ParamSpec& spec, double v) {
  return is_integer_type(spec.type) ? JsonValue(int64_t(std::llround(v))) : JsonValue(v);
}

double number_of(const JsonValue& v, double fallback) {
  return v.is_number() ? v.as_number() : fallback;
}

QHBoxLayout* row_layout(QWidget* owner) {
  auto* layout = new QHBoxLayout(owner);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(4);
  return layout;
}

QDoubleSpinBox* make_spin(const ParamSpec& spec, QWidget* parent) {
  auto* spin = new QDoubleSpinBox(parent);
  const bool integer = is_integer_type(spec.type);
  const double big = integer ? double(std::numeric_limits<int>::max()) : 1e9;
  spin->setRange(spec.min.value_or(-big), spec.max.value_or(big));
  spin->setDecimals(integer ? 0 : 3);
  if (!integer && spec.min && spec.max) spin->setSingleStep(std::max((*spec.max - *spec.min) / 100, 0.001));
  if (!spec.unit.empty()) spin->setSuffix(QStringLiteral(" ") + text_of(spec.unit));
  spin->setKeyboardTracking(false);
  spin->setMinimumWidth(70);
  return spin;
}

// A number: a spin box, with a slider beside it when the range is bounded.
class NumberEditor : public ParamEditor {
 public:
  NumberEditor(const ParamSpec& spec, QWidget* parent)
      : ParamEditor(parent), spec_(spec), spin_(make_spin(spec, this)) {
    auto* layout = row_layout(this);
    if (spec.min && spec.max && *spec.max > *spec.min) {
      slider_ = new QSlider(Qt::Horizontal, this);
      slider_->setRange(0, steps);
      layout->addWidget(slider_, 1);
      connect(slider_, &QSlider::valueChanged, this, [this](int s) {
        const double v = *spec_.min + (*spec_.max - *spec_.min) * s / steps;
        const QSignalBlocker block(spin_);
        spin_->setValue(v);
        emit edited(number_value(spec_, spin_->value()));
      });
    }
    layout->addWidget(spin_, slider_ ? 0 : 1);
    connect(spin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
      place_slider(v);
      emit edited(number_value(spec_, v));
    });
  }
  void set_value(const JsonValue& value) override {
    const QSignalBlocker block(spin_);
    spin_->setValue(number_of(value, 0));
    place_slider(spin_->value());
  }

 private:
  static constexpr int steps = 1000;
  void place_slider(double v) {
    if (!slider_) return;
    const QSignalBlocker block(slider_);
    slider_->setValue(int(std::lround((v - *spec_.min) / (*spec_.max - *spec_.min) * steps)));
  }
  ParamSpec spec_;
  QDoubleSpinBox* spin_;
  QSlider* slider_ = nullptr;
};

// float2/3/4 and int2: one spin box per component.
class VectorEditor : public ParamEditor {
 public:
  VectorEditor(const ParamSpec& spec, QWidget* parent) : ParamEditor(parent), spec_(spec) {
    auto* layout = row_layout(this);
    static const char* names[] = {"x", "y", "z", "w"};
    for (size_t i = 0; i < param_components(spec.type); ++i) {
      QDoubleSpinBox* spin = make_spin(spec, this);
      spin->setPrefix(QStringLiteral("%1 ").arg(names[i]));
      spin->setSuffix({});
      layout->addWidget(spin, 1);
      spins_.push_back(spin);
      connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] { emit edited(value()); });
    }
  }
  void set_value(const JsonValue& value) override {
    for (size_t i = 0; i < spins_.size(); ++i) {
      const QSignalBlocker block(spins_[i]);
      spins_[i]->setValue(value.is_array() && i < value.size() ? number_of(value.items()[i], 0) : 0);
    }
  }

 private:
  JsonValue value() const {
    JsonValue v = JsonValue::array();
    for (QDoubleSpinBox* spin : spins_) v.push(number_value(spec_, spin->value()));
    return v;
  }
  ParamSpec spec_;
  std::vector<QDoubleSpinBox*> spins_;
};

class BoolEditor : public ParamEditor {
 public:
  BoolEditor(QWidget* parent) : ParamEditor(parent), box_(new QCheckBox(this)) {
    row_layout(this)->addWidget(box_);
    connect(box_, &QCheckBox::toggled, this, [this](bool on) { emit edited(JsonValue(on)); });
  }
  void set_value(const JsonValue& value) override {
    const QSignalBlocker block(box_);
    box_->setChecked(value.is_bool() && value.as_bool());
  }

 private:
  QCheckBox* box_;
};

class EnumEditor : public ParamEditor {
 public:
  EnumEditor(const ParamSpec& spec, QWidget* parent) : ParamEditor(parent), combo_(new QComboBox(this)) {
    for (const std::string& v : spec.values) combo_->addItem(text_of(v));
    row_layout(this)->addWidget(combo_, 1);
    connect(combo_, &QComboBox::textActivated, this,
            [this](const QString& v) { emit edited(JsonValue(v.toStdString())); });
  }
  void set_value(const JsonValue& value) override {
    const QSignalBlocker block(combo_);
    combo_->setCurrentText(value.is_string() ? text_of(value.as_string()) : QString());
  }

 private:
  QComboBox* combo_;
};

// Strings, and paths with a file picker that keeps the file relative to the graph.
class TextEditor : public ParamEditor {
 public:
  TextEditor(const ParamSpec& spec, const QString& graph_dir, QWidget* parent)
      : ParamEditor(parent), line_(new QLineEdit(this)) {
    auto* layout = row_layout(this);
    layout->addWidget(line_, 1);
    connect(line_, &QLineEdit::editingFinished, this, [this] { emit edited(JsonValue(line_->text().toStdString())); });
    if (spec.type != ParamType::path) return;
    auto* browse = new QToolButton(this);
    browse->setText(QStringLiteral("…"));
    browse->setToolTip(tr("Choose a file"));
    layout->addWidget(browse);
    QStringList patterns;
    for (const std::string& e : spec.extensions) patterns << QStringLiteral("*") + text_of(e);
    const QString filter = patterns.isEmpty() ? QString() : tr("Accepted files (%1)").arg(patterns.join(' '));
    connect(browse, &QToolButton::clicked, this, [this, graph_dir, filter] {
      QString file = QFileDialog::getOpenFileName(this, tr("Choose a file"), graph_dir, filter);
      if (file.isEmpty()) return;
      if (!graph_dir.isEmpty()) file = QDir(graph_dir).relativeFilePath(file);
      line_->setText(file);
      emit edited(JsonValue(file.toStdString()));
    });
  }
  void set_value(const JsonValue& value) override {
    const QSignalBlocker block(line_);
    line_->setText(value.is_string() ? text_of(value.as_string()) : QString());
  }

 private:
  QLineEdit* line_;
};

}  // namespace

ParamEditor* make_param_editor(const ParamSpec& spec, const QString& graph_dir, QWidget* parent) {
  switch (spec.type) {
    case ParamType::float_:
    case ParamType::int_:
      return new NumberEditor(spec, parent);
    case ParamType::float2:
    case ParamType::float3:
    case ParamType::float4:
    case ParamType::int2:
      return new VectorEditor(spec, parent);
    case ParamType::bool_:
      return new BoolEditor(parent);
    case ParamType::enum_:
      return new EnumEditor(spec, parent);
    case ParamType::string:
    case ParamType::path:
      return new TextEditor(spec, graph_dir, parent);
  }
  return new TextEditor(spec, graph_dir, parent);
}

}  // namespace lg::editor
