/// @file candidate_proof.cpp
#include "primes/candidate_proof.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/error.hpp"
#include "primes/trial_division.hpp"

namespace tk::primes {

namespace {

/// Records name the proof's parameter as the theorems do.
const char* parameter_name(const std::string& test) { return test == "llr" ? "P" : "a"; }

std::uint64_t decimal_digits(const mpz_class& value) {
  // mpz_sizeinbase may overshoot by one: fix it with a comparison.
  std::size_t digits = mpz_sizeinbase(value.get_mpz_t(), 10);
  mpz_class ten;
  mpz_ui_pow_ui(ten.get_mpz_t(), 10, digits - 1);
  return value < ten ? digits - 1 : digits;
}

/// k*2^n-1 or k*2^n+1 with k odd and below 2^n (2^n-1 before 2^n+1), if
/// `value` is one of them.
std::optional<KbncForm> riesel_or_proth_form(const mpz_class& value) {
  if (value < 3) return std::nullopt;
  for (const int c : {-1, 1}) {
    KbncForm form{value - c, 2, 0, c};
    make_k_odd(form);
    if (mpz_sizeinbase(form.k.get_mpz_t(), 2) <= form.n) return form;
  }
  return std::nullopt;
}

/// Why a number (of the form given, if any) has no LLR or Proth proof.
std::string why_unprovable(const std::optional<KbncForm>& form) {
  if (!form || form->b != 2 || (form->c != 1 && form->c != -1) || form->k <= 0)
    return "it is not k*2^n-1 or k*2^n+1 with k below 2^n";
  KbncForm odd = *form;
  make_k_odd(odd);
  if (odd.n < (form->c < 0 ? 2u : 1u)) return form->c < 0 ? "LLR needs n >= 2" : "Proth needs n >= 1";
  if (mpz_sizeinbase(odd.k.get_mpz_t(), 2) > odd.n) return "k (made odd) is not below 2^n";
  return "k (made odd) has more than 64 bits";
}

}  // namespace

MemberProof prove_member(const Member& member, const ProofPlan& plan) {
  MemberProof proof;
  const Number& number = member.number;
  proof.digits = decimal_digits(number.value);
  // A number written out in digits or in another shape may still be
  // k*2^n+-1 (6143 = 3*2^11-1, 4^2+1 = 1*2^4+1): find that form, so it
  // gets a proof rather than BPSW.
  std::optional<KbncForm> found_form = number.form;
  if (!found_form || found_form->b != 2 || (found_form->c != 1 && found_form->c != -1))
    if (auto riesel_or_proth = riesel_or_proth_form(number.value)) found_form = riesel_or_proth;
  const auto& form = found_form;
  std::uint64_t k = 0, n = 0;
  bool special = form && form->b == 2 && (form->c == 1 || form->c == -1) && form->k > 0;
  if (special) {
    // k*2^n = (k/2)*2^(n+1): take every factor 2 out of k first.
    KbncForm odd = *form;
    make_k_odd(odd);
    n = odd.n;
    special = mpz_sizeinbase(odd.k.get_mpz_t(), 2) <= 64;
    if (special) k = mpz_get_ui(odd.k.get_mpz_t());
    special = special && (n >= 64 || k < (std::uint64_t(1) << n)) && n >= (form->c < 0 ? 2u : 1u);
  }
  proof.n = form ? n : 0;
  proof.text = special ? fmt::format("{}*2^{}{}", k, n, form->c < 0 ? "-1" : "+1")
               : form  ? kbnc_text(*form)
                       : number.value.get_str();
  // Results name the number as it was given (1338*2^1000-1 stays so, though
  // proved as 669*2^1001-1), so they can be matched with the input.
  // k*2^n+-1 keeps its "1*" as LLR's isLLRP and isProthP write it.
  const bool llr_shape = number.form && number.form->b == 2 && (number.form->c == 1 || number.form->c == -1);
  proof.name = llr_shape     ? fmt::format("{}*2^{}{:+d}", number.form->k.get_str(), number.form->n, number.form->c)
               : number.form ? kbnc_text(*number.form)
                             : number.value.get_str();
  // 3 = 1*2^2-1 is the one k*2^n-1 that trial division below does not settle
  // and LLR's P = 4 cannot prove (it needs 3 not to divide N).
  if (number.value == 3 && special && form->c < 0) {
    proof.verdict = Verdict::prime;
    proof.test = "trial";
    return proof;
  }
  // Nothing below 2 is prime, and trial division would name a false factor
  // (3 divides 0): say what mrtest says.
  if (number.value < 2) {
    const TestOutcome outcome = test_number(number, TestPlan{});
    proof.verdict = outcome.verdict;
    proof.test = "bpsw";
    proof.witness = outcome.witness;
    return proof;
  }
  // A small factor settles it at once (and keeps LLR's choice of P valid: P = 4 needs 3 not dividing N).
  if (const std::uint64_t p = trial_factor(number, 1000)) {
    proof.verdict = Verdict::composite;
    proof.test = "trial";
    proof.witness = fmt::format("factor {}", p);
    return proof;
  }
  if (!special && plan.require_proof)
    throw Error(fmt::format("{} cannot be proved: {}", proof.name, why_unprovable(form)));
  if (!special) {
    TestPlan bpsw;
    const TestOutcome outcome = test_number(number, bpsw);
    proof.verdict = std::min(outcome.verdict, Verdict::probable_prime);
    proof.test = "bpsw";
    proof.witness = outcome.witness;
    return proof;
  }
  const ProofOptions options = plan.options_for ? plan.options_for(proof.text) : ProofOptions{};
  const ProofResult result = form->c < 0 ? llr_prove(k, n, plan.start, options) : proth_prove(k, n, options);
  proof.verdict = result.verdict;
  proof.test = form->c < 0 ? "llr" : "proth";
  proof.parameter = result.parameter;
  if (result.verdict == Verdict::composite && result.parameter) proof.res64 = result.res64;
  if (result.verdict == Verdict::composite && !result.parameter)
    proof.witness = form->c < 0 ? "no P fits: a square or a small factor" : "no a fits: a square";
  return proof;
}

Verdict prove_candidate(const Candidate& candidate, const ProofPlan& plan, Record& record,
                        const std::function<void(const MemberProof&)>& on_member) {
  for (const char* owned : {"verdict", "test", "P", "a", "res64", "witness", "members"}) record.erase(owned);
  Verdict overall = Verdict::prime;
  Record members = Record::array();
  for (const Member& member : candidate.members) {
    const MemberProof proof = prove_member(member, plan);
    if (on_member) on_member(proof);
    overall = std::min(overall, proof.verdict);
    Record entry = Record::object();
    if (candidate.form) {
      entry["n"] = member.n;
      entry["c"] = member.c;
    }
    entry["verdict"] = std::string(verdict_name(proof.verdict));
    entry["test"] = proof.test;
    if (proof.parameter) entry[parameter_name(proof.test)] = proof.parameter;
    if (proof.res64) entry["res64"] = fmt::format("{:016X}", *proof.res64);
    if (!proof.witness.empty()) entry["witness"] = proof.witness;
    if (!candidate.form) {
      for (auto& [key, value] : entry.items()) record[key] = value;
    } else {
      members.push_back(std::move(entry));
    }
    if (proof.verdict == Verdict::composite || proof.verdict == Verdict::unknown) break;
  }
  if (candidate.form) {
    record["verdict"] = std::string(verdict_name(overall));
    const Record& last = members.back();
    record["test"] = last["test"];
    record["members"] = std::move(members);
  }
  return overall;
}

}  // namespace tk::primes
