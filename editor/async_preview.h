// Runs a PreviewRenderer off the UI thread: request() hands over the latest graph and port
// (replacing a request not yet started, so a slider drag renders only where it settles) and
// finished() arrives on the UI thread with the image, or an error, and how long it took.
#pragma once

#include <QObject>
#include <QSize>
#include <QString>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>

#include "editor/preview.h"

namespace lg::editor {

class AsyncPreview : public QObject {
  Q_OBJECT

 public:
  explicit AsyncPreview(std::unique_ptr<PreviewRenderer> renderer, QObject* parent = nullptr);
  ~AsyncPreview() override;  // finishes the render in progress, drops the rest

  void request(Graph graph, QSize size, PreviewPort port);

 signals:
  void finished(lg::editor::PreviewImage image, QString error, double milliseconds);

 private:
  void run();

  std::unique_ptr<PreviewRenderer> renderer_;  // used on the worker thread only
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<std::tuple<Graph, QSize, PreviewPort>> pending_;
  bool stopping_ = false;
  std::thread worker_;
};

}  // namespace lg::editor
