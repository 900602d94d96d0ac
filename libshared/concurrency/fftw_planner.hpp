/// @file fftw_planner.hpp
/// @brief FFTW's planner (creating and destroying plans, wisdom) is not
/// thread-safe; executing a plan is. One lock for every caller in the
/// process, so the prime and the control code never plan at once.
#pragma once

#include <mutex>

namespace tk {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex planner;
  return planner;
}

}  // namespace tk
