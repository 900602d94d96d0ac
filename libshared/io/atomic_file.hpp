/// @file atomic_file.hpp
/// @brief Replaces a file so that a crash at any moment leaves the old
/// content or the new, never half of it: write a temporary file, fsync it,
/// rename it over the old one, fsync the directory.
#pragma once

#include <string>
#include <string_view>

namespace tk::io {

/// `temporary` must be in the same directory as `path` and unique to the
/// writer (two writers of one path need two temporaries). Throws Error.
void write_file_atomically(const std::string& path, std::string_view bytes, const std::string& temporary);

}  // namespace tk::io
