/// @file prime_text_formats.cpp
#include "primes/prime_text_formats.hpp"

namespace tk::primes {

std::unique_ptr<io::LineDecoder> probe_prime_text_format(std::string_view, std::size_t) { return nullptr; }

}  // namespace tk::primes
