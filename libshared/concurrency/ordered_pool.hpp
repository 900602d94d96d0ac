/// @file ordered_pool.hpp
/// @brief Runs jobs on N threads and hands results back in submission order,
/// so `-j N` never reorders a tool's output.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace tk {

/// At most `window` jobs are in flight; submit() blocks (emitting finished
/// results) when the window is full. An exception thrown by `work` is
/// rethrown from submit()/finish() at that job's place in the order, after
/// every earlier result has been emitted.
template <class Job, class Result>
class OrderedPool {
 public:
  using Work = std::function<Result(Job&)>;
  using Emit = std::function<void(Result&)>;

  OrderedPool(unsigned threads, Work work, Emit emit, std::size_t window = 0)
      : work_(std::move(work)),
        emit_(std::move(emit)),
        window_(window ? window : 4 * static_cast<std::size_t>(threads)) {
    if (threads > 1)
      for (unsigned i = 0; i < threads; ++i) workers_.emplace_back([this] { run_worker(); });
  }

  ~OrderedPool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    work_ready_.notify_all();
    for (auto& worker : workers_) worker.join();
  }

  OrderedPool(const OrderedPool&) = delete;
  OrderedPool& operator=(const OrderedPool&) = delete;

  void submit(Job job) {
    if (workers_.empty()) {  // one thread: no queue, no locking
      Result result = work_(job);
      emit_(result);
      return;
    }
    {
      std::unique_lock lock(mutex_);
      slots_.push_back(Slot{std::move(job), {}, {}, false});
    }
    work_ready_.notify_one();
    drain(window_);
  }

  /// Waits for every job and emits the remaining results.
  void finish() {
    if (!workers_.empty()) drain(0);
  }

 private:
  struct Slot {
    Job job;
    std::optional<Result> result;
    std::exception_ptr error;
    bool taken;
  };

  /// Emits finished results from the head until at most `keep` jobs remain.
  void drain(std::size_t keep) {
    for (;;) {
      std::unique_lock lock(mutex_);
      if (slots_.empty()) return;
      const bool must_wait = slots_.size() > keep;
      auto head_done = [this] { return slots_.front().result || slots_.front().error; };
      if (!head_done()) {
        if (!must_wait) return;
        result_ready_.wait(lock, head_done);
      }
      Slot slot = std::move(slots_.front());
      slots_.pop_front();
      ++head_;
      lock.unlock();
      if (slot.error) std::rethrow_exception(slot.error);
      emit_(*slot.result);
    }
  }

  void run_worker() {
    for (;;) {
      std::unique_lock lock(mutex_);
      std::size_t index = 0;
      work_ready_.wait(lock, [&] {
        if (stopping_) return true;
        for (index = 0; index < slots_.size(); ++index)
          if (!slots_[index].taken) return true;
        return false;
      });
      if (stopping_) return;
      const std::uint64_t sequence = head_ + index;
      slots_[index].taken = true;
      Job job = std::move(slots_[index].job);
      lock.unlock();
      std::optional<Result> result;
      std::exception_ptr error;
      try {
        result.emplace(work_(job));
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      Slot& slot = slots_[sequence - head_];  // the deque only loses finished slots at the front
      slot.result = std::move(result);
      slot.error = error;
      lock.unlock();
      result_ready_.notify_all();
    }
  }

  Work work_;
  Emit emit_;
  std::size_t window_;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable work_ready_, result_ready_;
  std::deque<Slot> slots_;
  std::uint64_t head_ = 0;  // sequence number of slots_.front()
  bool stopping_ = false;
};

}  // namespace tk
