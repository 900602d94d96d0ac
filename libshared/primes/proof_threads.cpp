/// @file proof_threads.cpp
#include "primes/proof_threads.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tk::primes {

namespace {

// About 55 us of pause instructions here: a partner a stage behind arrives
// within that on an idle core; one that does not is likely descheduled.
constexpr int kSpins = 4096;

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

}  // namespace

void ProofThreads::Gate::wait_past(std::uint32_t seen) {
  for (int spin = 0; spin < kSpins; ++spin) {
    if (generation.load(std::memory_order_acquire) != seen) return;
    relax();
  }
  // Counted as a sleeper before the last look, so open() either sees the
  // sleeper (and wakes it) or has moved the generation on before that look.
  sleepers.fetch_add(1, std::memory_order_seq_cst);
  while (generation.load(std::memory_order_seq_cst) == seen) generation.wait(seen, std::memory_order_seq_cst);
  sleepers.fetch_sub(1, std::memory_order_relaxed);
}

void ProofThreads::Gate::open() {
  generation.fetch_add(1, std::memory_order_seq_cst);
  if (sleepers.load(std::memory_order_seq_cst) != 0) generation.notify_all();
}

ProofThreads::ProofThreads(unsigned count) : count_(count < 1 ? 1 : count) {
  workers_.reserve(count_ - 1);
  for (unsigned index = 1; index < count_; ++index) workers_.emplace_back([this, index] { serve(index); });
}

ProofThreads::~ProofThreads() {
  stopping_ = true;
  job_.open();
  for (std::thread& worker : workers_) worker.join();
}

void ProofThreads::serve(unsigned index) {
  std::uint32_t seen = 0;
  for (;;) {
    job_.wait_past(seen);
    seen = job_.generation.load(std::memory_order_acquire);
    if (stopping_) return;
    call_(context_, index);
    barrier();
  }
}

void ProofThreads::run_erased(void* context, void (*call)(void*, unsigned)) {
  context_ = context;
  call_ = call;
  if (count_ > 1) job_.open();
  call(context, 0);
  if (count_ > 1) barrier();  // every worker is done with this run
}

void ProofThreads::barrier() {
  if (count_ == 1) return;
  const std::uint32_t seen = barrier_.generation.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_) {
    arrived_.store(0, std::memory_order_relaxed);
    barrier_.open();
  } else {
    barrier_.wait_past(seen);
  }
}

}  // namespace tk::primes
