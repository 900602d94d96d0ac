/// @file prime_text_formats.hpp
/// @brief NewPGen and ABC/ABCD files, as LLR and PFGW read them, mapped
/// onto the shared candidate records.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "io/record_reader.hpp"

namespace tk::primes {

/// A decoder when `first_line` is a NewPGen or ABC/ABCD header, else nullptr.
std::unique_ptr<io::LineDecoder> probe_prime_text_format(std::string_view first_line, std::size_t max_bits);

}  // namespace tk::primes
