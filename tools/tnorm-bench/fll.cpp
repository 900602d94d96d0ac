/// @file fll.cpp
/// @brief tnorm-bench fll: the controller as fuzzylite FLL.
#include <cstdio>

#include "fuzzy/fll.hpp"
#include "io/error.hpp"
#include "modes.hpp"

namespace tnorm_bench {

using namespace tk;

void run_fll(const ControllerOptions& options) {
  const std::vector<TNorm> chosen = options.chosen_tnorms(false);
  if (chosen.size() > 1) throw UsageError("fll takes one --tnorm");
  const fuzzy::Engine engine = options.engine(chosen.empty() ? std::nullopt : std::optional<TNorm>(chosen[0]));
  const std::string text = fuzzy::write_fll(engine);
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) throw Error("write error on standard output");
}

}  // namespace tnorm_bench
