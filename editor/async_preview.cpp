#include "editor/async_preview.h"

#include <chrono>

namespace lg::editor {

AsyncPreview::AsyncPreview(std::unique_ptr<PreviewRenderer> renderer, QObject* parent)
    : QObject(parent), renderer_(std::move(renderer)), worker_([this] { run(); }) {
  qRegisterMetaType<PreviewImage>();  // finished() crosses threads
}

AsyncPreview::~AsyncPreview() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  worker_.join();
}

void AsyncPreview::request(Graph graph, QSize size, PreviewPort port) {
  {
    std::lock_guard lock(mutex_);
    pending_.emplace(std::move(graph), size, std::move(port));
  }
  wake_.notify_one();
}

void AsyncPreview::run() {
  for (;;) {
    std::tuple<Graph, QSize, PreviewPort> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || pending_; });
      if (stopping_) return;
      job = std::move(*pending_);
      pending_.reset();
    }
    const auto start = std::chrono::steady_clock::now();
    QString error;
    PreviewImage image = renderer_->render(std::get<0>(job), std::get<1>(job), std::get<2>(job), &error);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // Emitted on this thread: Qt queues it to the receivers' (UI) thread.
    emit finished(std::move(image), error, ms);
  }
}

}  // namespace lg::editor
