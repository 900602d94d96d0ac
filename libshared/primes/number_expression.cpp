/// @file number_expression.cpp
#include "primes/number_expression.hpp"

#include <cmath>
#include <string>

#include "io/error.hpp"

namespace tk::primes {

namespace {

/// A parsed value and, while the text still reads as [k*]b^n[+-c], that shape.
struct Term {
  mpz_class value;
  bool literal = false;          // a bare integer
  std::optional<KbncForm> form;  // b^n or k*b^n or k*b^n+c
};

std::size_t bit_length(const mpz_class& v) { return mpz_sizeinbase(v.get_mpz_t(), 2); }

class Parser {
 public:
  Parser(std::string_view text, std::size_t max_bits) : text_(text), max_bits_(max_bits) {}

  Term parse() {
    Term result = expression();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(message + " at column " + std::to_string(pos_ + 1) + " of '" + shortened() + "'");
  }
  std::string shortened() const {
    return text_.size() <= 40 ? std::string(text_) : std::string(text_.substr(0, 37)) + "...";
  }
  void check_bits(double bits) const {
    if (bits > static_cast<double>(max_bits_) + 1)
      throw Error("number has about " + std::to_string(static_cast<unsigned long long>(std::min(bits, 1e18))) +
                  " bits, more than --max-bits " + std::to_string(max_bits_));
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  bool accept(std::string_view token) {
    skip_space();
    if (text_.substr(pos_, token.size()) == token) {
      pos_ += token.size();
      return true;
    }
    return false;
  }
  struct Depth {  // bounds recursion so "((((...))))" cannot exhaust the stack
    explicit Depth(Parser& p) : parser(p) {
      if (++parser.depth_ > 200) parser.fail("expression nested too deeply");
    }
    ~Depth() { --parser.depth_; }
    Parser& parser;
  };

  Term expression() {
    Depth guard(*this);
    Term left = product();
    for (;;) {
      int sign = 0;
      if (accept("+")) sign = 1;
      else if (accept("-")) sign = -1;
      else return left;
      Term right = product();
      Term sum;
      if (sign > 0) sum.value = left.value + right.value;
      else sum.value = left.value - right.value;
      // k*b^n followed by a word-sized constant keeps its shape.
      if (left.form && left.form->c == 0 && right.literal && mpz_fits_slong_p(right.value.get_mpz_t()) &&
          right.value < (mpz_class(1) << 62)) {
        sum.form = left.form;
        sum.form->c = sign * mpz_get_si(right.value.get_mpz_t());
      }
      left = std::move(sum);
    }
  }

  Term product() {
    Term left = unary();
    for (;;) {
      char op = 0;
      skip_space();
      if (text_.substr(pos_, 2) == "**") return left;  // handled in power()
      if (accept("*")) op = '*';
      else if (accept("/")) op = '/';
      else if (accept("%")) op = '%';
      else return left;
      Term right = unary();
      Term out;
      if (op == '*') {
        check_bits(static_cast<double>(bit_length(left.value) + bit_length(right.value)));
        out.value = left.value * right.value;
        if (left.literal && right.form && right.form->k == 1 && right.form->c == 0) {
          out.form = right.form;
          out.form->k = left.value;
        } else if (right.literal && left.form && left.form->k == 1 && left.form->c == 0) {
          out.form = left.form;
          out.form->k = right.value;
        }
      } else {
        if (right.value == 0) fail("division by zero");
        if (op == '/') {
          if (!mpz_divisible_p(left.value.get_mpz_t(), right.value.get_mpz_t())) fail("division is not exact");
          mpz_divexact(out.value.get_mpz_t(), left.value.get_mpz_t(), right.value.get_mpz_t());
        } else {
          mpz_tdiv_r(out.value.get_mpz_t(), left.value.get_mpz_t(), right.value.get_mpz_t());
        }
      }
      left = std::move(out);
    }
  }

  Term unary() {
    Depth guard(*this);
    if (accept("-")) {
      Term t = unary();
      t.value = -t.value;
      t.literal = false;
      t.form.reset();
      return t;
    }
    if (accept("+")) return unary();
    return power();
  }

  Term power() {
    Term base = postfix();
    if (!accept("^") && !accept("**")) return base;
    Term exponent = unary();  // right associative: 2^3^2 = 2^9
    if (exponent.value < 0) fail("negative exponent");
    if (!mpz_fits_ulong_p(exponent.value.get_mpz_t())) check_bits(1e30);
    const unsigned long e = mpz_get_ui(exponent.value.get_mpz_t());
    const mpz_class magnitude = abs(base.value);
    if (magnitude > 1) check_bits(static_cast<double>(e) * std::log2(magnitude.get_d()));
    Term out;
    mpz_pow_ui(out.value.get_mpz_t(), base.value.get_mpz_t(), e);
    if (base.literal && exponent.literal && base.value >= 2 && mpz_fits_ulong_p(base.value.get_mpz_t()))
      out.form = KbncForm{1, mpz_get_ui(base.value.get_mpz_t()), e, 0};
    return out;
  }

  Term postfix() {
    Term t = primary();
    for (;;) {
      if (accept("!")) t = factorial(t, false);
      else if (accept("#")) t = factorial(t, true);
      else return t;
    }
  }

  Term factorial(const Term& arg, bool primorial) {
    if (arg.value < 0 || !mpz_fits_ulong_p(arg.value.get_mpz_t())) fail("factorial or primorial of a bad argument");
    const unsigned long n = mpz_get_ui(arg.value.get_mpz_t());
    // log2(n!) = lgamma(n+1)/ln 2; log2(p#) is about p / ln 2.
    check_bits(primorial ? 1.4427 * static_cast<double>(n) : std::lgamma(static_cast<double>(n) + 1) / std::log(2.0));
    Term out;
    if (primorial) mpz_primorial_ui(out.value.get_mpz_t(), n);
    else mpz_fac_ui(out.value.get_mpz_t(), n);
    return out;
  }

  Term primary() {
    skip_space();
    if (pos_ == text_.size()) fail("missing number");
    if (accept("(")) {
      Term inner = expression();
      if (!accept(")")) fail("missing ')'");
      inner.literal = false;
      return inner;
    }
    const std::size_t start = pos_;
    int radix = 10;
    if (text_.substr(pos_, 2) == "0x" || text_.substr(pos_, 2) == "0X") {
      radix = 16;
      pos_ += 2;
    }
    const std::size_t digits_start = pos_;
    while (pos_ < text_.size() && (radix == 16 ? std::isxdigit(static_cast<unsigned char>(text_[pos_]))
                                               : std::isdigit(static_cast<unsigned char>(text_[pos_]))))
      ++pos_;
    if (pos_ == digits_start) {
      pos_ = start;
      fail(start < text_.size() ? "unexpected '" + std::string(1, text_[start]) + "'" : "missing number");
    }
    const std::string_view digits = text_.substr(digits_start, pos_ - digits_start);
    check_bits(static_cast<double>(digits.size()) * (radix == 16 ? 4.0 : 3.3219280948873622) - 4);
    Term t;
    t.literal = true;
    t.value.set_str(std::string(digits), radix);
    return t;
  }

  std::string_view text_;
  std::size_t max_bits_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

Number parse_number(std::string_view text, std::size_t max_bits) {
  // Fast path for plain decimals that fit a word: most lines of a big run.
  if (!text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string_view::npos) {
    unsigned long value = 0;
    for (char ch : text) value = value * 10 + static_cast<unsigned long>(ch - '0');
    const std::size_t bits = value == 0 ? 1 : static_cast<std::size_t>(64 - __builtin_clzl(value));
    if (bits > max_bits)
      throw Error("number has " + std::to_string(bits) + " bits, more than --max-bits " + std::to_string(max_bits));
    return Number{mpz_class(value), std::nullopt};
  }
  Parser parser(text, max_bits);
  Term term = parser.parse();
  Number number{std::move(term.value), std::nullopt};
  if (term.form && term.form->k > 0 && mpz_sizeinbase(number.value.get_mpz_t(), 2) <= max_bits) number.form = term.form;
  if (mpz_sizeinbase(number.value.get_mpz_t(), 2) > max_bits)
    throw Error("number has " + std::to_string(mpz_sizeinbase(number.value.get_mpz_t(), 2)) +
                " bits, more than --max-bits " + std::to_string(max_bits));
  return number;
}

bool looks_like_number(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return false;
  const char c = text[first];
  if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '(' || c == '-' || c == '+')) return false;
  return text.find_first_not_of("0123456789xXabcdefABCDEF+-*/%^!#() \t") == std::string_view::npos;
}

}  // namespace tk::primes
