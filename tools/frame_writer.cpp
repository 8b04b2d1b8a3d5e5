// frame_writer.cpp — the writer threads and their queue (frame_writer.h).
#include "tools/frame_writer.h"

#include <algorithm>

#include <pthread.h>
#include <sched.h>

namespace phongvk {

FrameWriter::FrameWriter(int threads, int queueFrames, int pngLevel, Written written)
    : queueFrames_(size_t(std::max(queueFrames, 1))), written_(std::move(written)) {
  std::vector<PngEncoder> encoders;  // made first: a bad level throws before any thread starts
  for (int i = 0; i < std::max(threads, 1); ++i) encoders.emplace_back(pngLevel);
  for (PngEncoder& encoder : encoders) threads_.emplace_back(&FrameWriter::run, this, std::move(encoder));
}

FrameWriter::~FrameWriter() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

int FrameWriter::defaultThreads() {
  const int cores = int(std::thread::hardware_concurrency());
  return std::max(cores - 1, 1);
}

void FrameWriter::rethrowFailure() {
  if (failure_) std::rethrow_exception(failure_);
}

void FrameWriter::push(FrameFile frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return failure_ || queue_.size() < queueFrames_; });
  rethrowFailure();
  queue_.push_back(std::move(frame));
  lock.unlock();
  changed_.notify_all();
}

void FrameWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return failure_ || (queue_.empty() && busy_ == 0); });
  rethrowFailure();
}

Image FrameWriter::spareImage() {
  const std::lock_guard lock(mutex_);
  if (spares_.empty()) return {};
  Image image = std::move(spares_.back());
  spares_.pop_back();
  return image;
}

void FrameWriter::run(PngEncoder encoder) {
  // Idle priority: a no-op where the system refuses it, which only costs speed.
  sched_param idle{};
  (void)pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle);
  for (;;) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return stopping_ || failure_ || !queue_.empty(); });
    if (failure_ || queue_.empty()) return;  // stopping, with nothing left to write
    FrameFile frame = std::move(queue_.front());
    queue_.pop_front();
    ++busy_;
    lock.unlock();
    changed_.notify_all();  // room in the queue
    std::exception_ptr failure;
    try {
      encoder.write(frame.path, frame.image);
      if (written_) {
        const std::lock_guard writtenLock(writtenMutex_);
        written_(frame);
      }
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    --busy_;
    spares_.push_back(std::move(frame.image));
    if (failure && !failure_) failure_ = failure;
    lock.unlock();
    changed_.notify_all();
  }
}

}  // namespace phongvk
