/// @file fuzz_number_expression.cpp
/// @brief libFuzzer target: bytes as the text of a number or expression.
///
/// Feeds the input to tk::primes::parse_number (max 4096 bits, so the fuzzer
/// is not slowed by huge numbers), looks_like_number and
/// record_from_number_text, then reads that record back with
/// candidate_from_record. tk::Error is the expected rejection; any other
/// exception, crash, sanitizer report, hang or huge allocation is a bug.
///
/// Oracles (switch off by name with TK_FUZZ_SKIP=a,b while a finding is open):
///   max_bits   a returned number never has more than max_bits (4096) bits
///   small_max_bits  the same with a small bound, 16
///   form       a returned k*b^n+c shape evaluates to the returned value
///   roundtrip  record_from_number_text accepts what parse_number accepts,
///              and candidate_from_record reads that record back to the
///              same value
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "io/error.hpp"
#include "primes/candidate.hpp"
#include "primes/number.hpp"
#include "primes/number_expression.hpp"

namespace {

constexpr std::size_t kMaxBits = 4096;
constexpr std::size_t kSmallMaxBits = 16;

std::size_t bits_of(const mpz_class& v) { return mpz_sizeinbase(v.get_mpz_t(), 2); }

std::string show(std::string_view text) {
  return "'" + std::string(text.substr(0, 200)) + (text.size() > 200 ? "...'" : "'");
}

void check_max_bits(std::string_view text, std::size_t max_bits) {
  tk::primes::Number number;
  try {
    number = tk::primes::parse_number(text, max_bits);
  } catch (const tk::Error&) {
    return;
  }
  if (tk::fuzz::oracle_enabled("small_max_bits") && bits_of(number.value) > max_bits)
    tk::fuzz::invariant_failed("small_max_bits", "parse_number(" + show(text) + ", " + std::to_string(max_bits) +
                                                     ") returned a number of " + std::to_string(bits_of(number.value)) +
                                                     " bits");
}

void run(std::string_view text) {
  (void)tk::primes::looks_like_number(text);

  bool parsed = false;
  tk::primes::Number number;
  try {
    number = tk::primes::parse_number(text, kMaxBits);
    parsed = true;
  } catch (const tk::Error&) {
  }
  if (parsed) {
    if (tk::fuzz::oracle_enabled("max_bits") && bits_of(number.value) > kMaxBits)
      tk::fuzz::invariant_failed(
          "max_bits", "parse_number(" + show(text) + ") returned " + std::to_string(bits_of(number.value)) + " bits");
    if (number.form && tk::fuzz::oracle_enabled("form")) {
      mpz_class again;
      try {
        again = tk::primes::evaluate_kbnc(*number.form, kMaxBits);
      } catch (const tk::Error& e) {
        tk::fuzz::invariant_failed("form", "form " + tk::primes::kbnc_text(*number.form) + " of " + show(text) +
                                               " does not evaluate: " + e.what());
      }
      if (again != number.value)
        tk::fuzz::invariant_failed("form", "form " + tk::primes::kbnc_text(*number.form) + " of " + show(text) +
                                               " is " + again.get_str() + ", value is " + number.value.get_str());
    }
  }

  tk::Record record;
  bool recorded = false;
  try {
    record = tk::primes::record_from_number_text(text, kMaxBits);
    recorded = true;
  } catch (const tk::Error& e) {
    if (parsed && tk::fuzz::oracle_enabled("roundtrip"))
      tk::fuzz::invariant_failed(
          "roundtrip", "parse_number accepts " + show(text) + " but record_from_number_text throws: " + e.what());
  }
  if (recorded && parsed && tk::fuzz::oracle_enabled("roundtrip")) {
    const std::string json = record.dump(-1, ' ', false, tk::Record::error_handler_t::replace);
    tk::primes::Candidate candidate;
    try {
      candidate = tk::primes::candidate_from_record(record, kMaxBits);
    } catch (const tk::Error& e) {
      tk::fuzz::invariant_failed(
          "roundtrip", "record " + json + " from " + show(text) + " is rejected by candidate_from_record: " + e.what());
    }
    if (candidate.form || candidate.members.size() != 1 || candidate.members[0].number.value != number.value)
      tk::fuzz::invariant_failed("roundtrip",
                                 "record " + json + " from " + show(text) + " reads back as a different candidate");
  }

  check_max_bits(text, kSmallMaxBits);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // No catch here: an exception other than tk::Error reaches std::terminate
  // while its throw site is still on the stack, so the report shows it.
  run(text);
  return 0;
}
