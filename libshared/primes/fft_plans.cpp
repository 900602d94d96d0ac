/// @file fft_plans.cpp
#include "primes/fft_plans.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <string>

#include "concurrency/fftw_planner.hpp"
#include "io/error.hpp"

namespace tk::primes {

namespace {

// FFTW_ESTIMATE: measured here (FFTW 3.3.10, Debian), its plans run as
// fast as FFTW_MEASURE's at 3584, 9216, 18432 and 40960 (0.048 ms for both
// transforms at 18432), while measuring costs 0.7 to 3 CPU seconds a
// length: more than a tenth of the 51,779-digit proof.
constexpr unsigned kPlanFlags = FFTW_ESTIMATE;

// The plans live until exit, then go back to FFTW (leak checkers see
// memory that only a destroyed map pointed to as lost).
struct PlanCache {
  std::map<std::size_t, RealFftPlans> plans;
  ~PlanCache() {
    for (auto& [length, pair] : plans) {
      fftw_destroy_plan(pair.forward);
      fftw_destroy_plan(pair.inverse);
    }
    fftw_cleanup();
  }
};

}  // namespace

const RealFftPlans* real_fft_plans(std::size_t length) {
  static PlanCache plan_cache;
  auto& cache = plan_cache.plans;
  std::lock_guard lock(fftw_planner_mutex());
  static const bool system_wisdom = fftw_import_system_wisdom() != 0;  // /etc/fftw/wisdom, if the admin made one
  (void)system_wisdom;
  auto found = cache.find(length);
  if (found != cache.end()) return &found->second;
  // Planning may overwrite its arrays: plan on scratch arrays, then execute
  // on each squarer's own (allocated alike, so aligned alike).
  double* real = fftw_alloc_real(length);
  fftw_complex* spectrum = fftw_alloc_complex(length / 2 + 1);
  const int n = static_cast<int>(length);
  const unsigned flags = kPlanFlags;
  RealFftPlans plans;
  plans.forward = fftw_plan_dft_r2c_1d(n, real, spectrum, flags);  // preserves its input (FFTW's default for r2c)
  plans.inverse = fftw_plan_dft_c2r_1d(n, spectrum, real, flags);
  fftw_free(real);
  fftw_free(spectrum);
  if (!plans.forward || !plans.inverse)
    throw Error("FFTW could not plan a transform of length " + std::to_string(length));
  return &cache.emplace(length, plans).first->second;
}

void square_by_real_fft(const RealFftPlans& plans, double* input, fftw_complex* spectrum, double* output,
                        std::size_t length) {
  fftw_execute_dft_r2c(plans.forward, input, spectrum);
  for (std::size_t j = 0; j <= length / 2; ++j) {
    const double re = spectrum[j][0], im = spectrum[j][1];
    spectrum[j][0] = re * re - im * im;
    spectrum[j][1] = 2.0 * re * im;
  }
  fftw_execute_dft_c2r(plans.inverse, spectrum, output);
}

const std::vector<std::size_t>& fast_fft_lengths() {
  static const std::vector<std::size_t> lengths = [] {
    std::vector<std::size_t> all;
    for (std::size_t power = 64; power <= (std::size_t{1} << 24); power *= 2)
      for (std::size_t odd : {1, 3, 5, 7, 9}) all.push_back(odd * power);
    std::sort(all.begin(), all.end());
    return all;
  }();
  return lengths;
}

}  // namespace tk::primes
