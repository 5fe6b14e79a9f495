#include "editor/async_preview.h"

#include <chrono>

namespace lg::editor {

AsyncPreview::AsyncPreview(std::unique_ptr<PreviewRenderer> renderer, QObject* parent)
    : QObject(parent), renderer_(std::move(renderer)), worker_([this] { run(); }) {}

AsyncPreview::~AsyncPreview() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  worker_.join();
}

void AsyncPreview::request(Graph graph, QSize size) {
  {
    std::lock_guard lock(mutex_);
    pending_.emplace(std::move(graph), size);
  }
  wake_.notify_one();
}

void AsyncPreview::run() {
  for (;;) {
    std::pair<Graph, QSize> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || pending_; });
      if (stopping_) return;
      job = std::move(*pending_);
      pending_.reset();
    }
    const auto start = std::chrono::steady_clock::now();
    QString error;
    QImage image = renderer_->render(job.first, job.second, &error);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // Emitted on this thread: Qt queues it to the receivers' (UI) thread.
    emit finished(std::move(image), error, ms);
  }
}

}  // namespace lg::editor
