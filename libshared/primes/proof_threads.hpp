/// @file proof_threads.hpp
/// @brief The threads one proof's squarings are split over: created once
/// (per proof), then each squaring runs a few parallel steps on them, with
/// barriers between the stages that must follow one another. Waiting
/// spins briefly, then sleeps (a futex under std::atomic::wait): the host
/// is shared, and a barrier spinning on a descheduled partner would burn
/// the core that partner needs.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <type_traits>
#include <vector>

namespace tk::primes {

class ProofThreads {
 public:
  /// `count` threads in all: the caller's and count - 1 new ones.
  explicit ProofThreads(unsigned count);
  ProofThreads(const ProofThreads&) = delete;
  ProofThreads& operator=(const ProofThreads&) = delete;
  ~ProofThreads();

  unsigned count() const { return count_; }

  /// Runs work(index) on every thread, index < count() (the caller's is
  /// 0), and returns when all have finished. `work` must not throw.
  template <class Work>
  void run(Work&& work) {
    run_erased(&work,
               [](void* context, unsigned index) { (*static_cast<std::remove_reference_t<Work>*>(context))(index); });
  }

  /// Inside run(): returns when every thread has reached it; what each
  /// wrote before is then seen by all.
  void barrier();

 private:
  /// A generation counter that waiters see move on.
  struct Gate {
    std::atomic<std::uint32_t> generation{0};
    std::atomic<std::uint32_t> sleepers{0};
    /// Returns once generation differs from `seen` (read before waiting).
    void wait_past(std::uint32_t seen);
    void open();
  };

  void run_erased(void* context, void (*call)(void*, unsigned));
  void serve(unsigned index);

  unsigned count_;
  Gate job_;      ///< moves on for each run() (and to stop)
  Gate barrier_;  ///< moves on when the last thread reaches barrier()
  std::atomic<unsigned> arrived_{0};
  void* context_ = nullptr;
  void (*call_)(void*, unsigned) = nullptr;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

/// Where part `part` of `parts` starts in [0, units), the units shared out
/// in order (part `parts` gives `units`): each thread's range of a split.
inline std::size_t share(std::size_t units, unsigned part, unsigned parts) { return units * part / parts; }

}  // namespace tk::primes
