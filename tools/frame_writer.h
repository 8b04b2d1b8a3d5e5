// frame_writer.h — frames encoded and written as PNG files on threads of their own while the next
// frames render (`phongvk sequence` writes its frames so): a bounded queue of rendered frames, so
// memory stays a few frames deep however fast rendering runs, each taken by one writer thread with
// its own PngEncoder. The writer threads run at idle priority (SCHED_IDLE): on a CPU Vulkan device
// or the reference, whose threads take every core in bursts, they use the gaps between them.
#pragma once

#include "phongvk/image.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace phongvk {

struct FrameFile {
  int index = 0;     // the frame's number in the sequence
  std::string path;  // where its PNG goes
  Image image;
};

class FrameWriter {
 public:
  // Called on a writer thread once a frame's file is in place, one call at a time (the writer
  // holds a lock around it), in the order frames finish, which with several threads is not
  // always the order they were queued.
  using Written = std::function<void(const FrameFile&)>;

  // `threads` writer threads, at most `queueFrames` frames waiting for one. Throws
  // ArgumentError for a PNG level out of range.
  FrameWriter(int threads, int queueFrames, int pngLevel, Written written = {});
  // Stops the threads once the queue is empty; a frame still waiting is written first.
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Queues a frame, waiting while the queue is full. Rethrows the first writer error (an
  // OutputError naming the file), after which nothing more is written.
  void push(FrameFile frame);
  // Waits until every queued frame is written; rethrows the first writer error.
  void finish();
  // The image of a frame already written, to render the next one into (Renderer::render reuses
  // its storage), or an empty one.
  Image spareImage();

  // Writer threads for this machine: one core is left to rendering, whose own threads (a CPU
  // Vulkan device, the reference) share the rest; at least one.
  static int defaultThreads();

 private:
  void run(PngEncoder encoder);
  void rethrowFailure();  // with mutex_ held

  const size_t queueFrames_;
  Written written_;
  std::mutex mutex_;
  std::mutex writtenMutex_;
  std::condition_variable changed_;
  std::deque<FrameFile> queue_;
  std::vector<Image> spares_;
  int busy_ = 0;          // frames being encoded or written now
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::vector<std::thread> threads_;
};

}  // namespace phongvk
