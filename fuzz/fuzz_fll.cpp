/// @file fuzz_fll.cpp
/// @brief libFuzzer target: the bytes as one FLL file through
/// tk::fuzzy::read_fll. Seeds in fuzz/seeds/fuzz_fll/ (the controllers of
/// test/fixtures/fll), dictionary fuzz/dicts/fll.dict, run with
/// -max_len=4096.
///
/// tk::Error is the expected rejection; any other exception, crash,
/// sanitizer report, hang or huge allocation is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   roundtrip  write_fll of what was read reads back to an equal engine
///              (engine_difference is empty)
///   fixpoint   and writing that again gives the same text
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "fuzzy/fll.hpp"
#include "io/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using tk::fuzz::invariant_failed;
  using tk::fuzz::oracle_enabled;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  tk::fuzzy::Engine engine;
  try {
    engine = tk::fuzzy::read_fll(bytes, "fuzz.fll");
  } catch (const tk::Error&) {
    return 0;  // the expected rejection; anything else reaches std::terminate
  }
  // From here on an Error is a finding: what was read must be writable and
  // read back.
  std::string text;
  tk::fuzzy::Engine again;
  try {
    text = tk::fuzzy::write_fll(engine);
    again = tk::fuzzy::read_fll(text, "written.fll");
  } catch (const tk::Error& e) {
    invariant_failed("roundtrip", e.located_message() + "\n" + text);
  }
  if (oracle_enabled("roundtrip")) {
    const std::string difference = tk::fuzzy::engine_difference(engine, again);
    if (!difference.empty()) invariant_failed("roundtrip", difference + "\n" + text);
  }
  if (oracle_enabled("fixpoint") && tk::fuzzy::write_fll(again) != text)
    invariant_failed("fixpoint", "second write differs from\n" + text);
  return 0;
}
