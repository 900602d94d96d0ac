/// @file gaussian_noise.hpp
/// @brief Seeded Gaussian noise for the simulations (sensor readings,
/// spindle-load measurements): the same seed gives the same noise with any
/// standard library and on any machine.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tk::sim {

/// Box-Muller over mt19937_64, whose output the C++ standard fixes
/// (std::normal_distribution's algorithm is left to the implementation).
class GaussianNoise {
 public:
  GaussianNoise(double sigma, std::uint64_t seed) : sigma_(sigma), random_(seed) {}

  /// The next deviate, standard deviation sigma; 0 without drawing when sigma is 0.
  double next() {
    if (sigma_ == 0) return 0;
    if (has_spare_) {
      has_spare_ = false;
      return sigma_ * spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: the log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2 * std::numbers::pi * u2);
    has_spare_ = true;
    return sigma_ * radius * std::cos(2 * std::numbers::pi * u2);
  }

 private:
  double uniform() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }  // [0, 1)

  double sigma_;
  std::mt19937_64 random_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace tk::sim
