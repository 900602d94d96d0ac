/// @file dxf_reader.cpp
/// @brief The top layer of the DXF reader: the file into memory, then the
/// sections. HEADER gives $ACADVER and $INSUNITS, ENTITIES goes to the
/// EntityBuilder, every other section (BLOCKS included) is passed over.
#include "cad/dxf_reader.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

#include "cad/dxf_entities.hpp"
#include "cad/dxf_tags.hpp"
#include "io/error.hpp"

namespace tk::cad {

namespace {

using dxf::Tag;
using dxf::TagReader;

bool is(const Tag& tag, std::string_view text) { return tag.code == 0 && tag.text == text; }

/// Where a section stops: at its ENDSEC (then `tag` is the tag after it),
/// or at a SECTION or EOF that comes first (a missing ENDSEC; then `tag` is
/// that one). The result is false at the end of the data.
bool ends_section(TagReader& tags, Tag& tag, bool& stop) {
  stop = false;
  if (tag.code != 0) return true;
  if (tag.text == "ENDSEC") {
    stop = true;
    return tags.next(tag);
  }
  stop = tag.text == "SECTION" || tag.text == "EOF";
  return true;
}

bool read_header(TagReader& tags, Tag& tag, Drawing& drawing) {
  std::string_view variable;
  bool stop = false;
  while (tags.next(tag)) {
    if (tag.code == 0) {
      const bool more = ends_section(tags, tag, stop);
      if (stop) return more;
      continue;
    }
    if (tag.code == 9) {
      variable = tag.text;
    } else if (tag.code == 1 && variable == "$ACADVER") {
      drawing.version = tag.text;
    } else if (tag.code == 70 && variable == "$INSUNITS") {
      const std::int64_t units = tags.integer(tag);
      if (units < INT_MIN || units > INT_MAX) tags.fail(tag, "number out of range for $INSUNITS");
      drawing.insunits = static_cast<int>(units);
    }
  }
  return false;
}

/// One builder serves every ENTITIES section of a file, so that entity
/// indices and layers carry on from one to the next.
bool read_entities(TagReader& tags, Tag& tag, std::size_t section_start, dxf::EntityBuilder& builder) {
  bool stop = false;
  while (tags.next(tag)) {
    if (tag.code == 0) {
      if (tag.text == "ENDSEC" || tag.text == "SECTION" || tag.text == "EOF") {
        builder.finish();
        return ends_section(tags, tag, stop);
      }
      builder.start(tag);
    } else {
      builder.add(tag);
    }
  }
  // A file cut short here may have lost entities: better said than guessed.
  tags.fail_at(section_start, "the ENTITIES section has no end (ENDSEC): the file is truncated");
}

bool skip_section(TagReader& tags, Tag& tag) {
  bool stop = false;
  while (tags.next(tag)) {
    if (tag.code != 0) continue;
    const bool more = ends_section(tags, tag, stop);
    if (stop) return more;
  }
  return false;
}

}  // namespace

Drawing read_dxf(std::string_view contents, const std::string& name, const DxfReadOptions& options) {
  TagReader tags(contents, name);
  Drawing drawing;
  drawing.binary = tags.binary();
  dxf::EntityBuilder builder(drawing, tags, options);
  bool have_entities = false;
  Tag tag;
  bool more = tags.next(tag);
  while (more) {
    if (is(tag, "EOF")) break;
    if (!is(tag, "SECTION")) {  // tags between sections, a stray ENDSEC: passed over
      more = tags.next(tag);
      continue;
    }
    const std::size_t section_start = tags.start_of(tag);
    if (!tags.next(tag)) tags.fail_at(section_start, "SECTION without a name at the end of the file");
    if (tag.code != 2)
      tags.fail(tag,
                "expected the section name (group code 2) after SECTION, found group code " + std::to_string(tag.code));
    if (tag.text == "HEADER") {
      more = read_header(tags, tag, drawing);
    } else if (tag.text == "ENTITIES") {
      have_entities = true;
      more = read_entities(tags, tag, section_start, builder);
    } else {
      more = skip_section(tags, tag);
    }
  }
  if (!have_entities) throw Error("no ENTITIES section", {name, 0});
  return drawing;
}

namespace {

/// Refuses what cannot be a DXF file while it is read, so that /dev/zero or
/// an endless line fails at once instead of filling memory: a NUL byte in
/// text that does not start with the binary sentinel, a line over 64 MiB,
/// a file over 1 GiB.
class ArrivingText {
 public:
  static constexpr std::size_t kMaxBytes = std::size_t{1} << 30, kMaxLine = std::size_t{64} << 20;

  /// `all` is everything read so far; `at_end` once the input has ended.
  void check(std::string_view all, bool at_end, const std::string& name) {
    if (all.size() > kMaxBytes) throw Error("larger than 1 GiB: not a part drawing", {name, 0});
    if (!binary_known_) {
      if (all.size() < dxf::kBinarySentinel.size() && !at_end) return;
      binary_known_ = true;
      binary_ = all.starts_with(dxf::kBinarySentinel);
    }
    if (binary_) return;
    for (; checked_ < all.size(); ++checked_) {
      if (all[checked_] == '\n') {
        ++lines_;
        line_start_ = checked_ + 1;
      } else if (all[checked_] == '\0') {
        throw Error("binary data (NUL byte) in text input", {name, lines_ + 1});
      }
    }
    if (all.size() - line_start_ > kMaxLine) throw Error("line longer than 64 MiB", {name, lines_ + 1});
  }

 private:
  bool binary_known_ = false, binary_ = false;
  std::size_t checked_ = 0, lines_ = 0, line_start_ = 0;
};

}  // namespace

Drawing read_dxf_file(const std::string& path, const DxfReadOptions& options) {
  const bool standard_input = path == "-";
  const std::string name = standard_input ? "<stdin>" : path;
  std::FILE* file = standard_input ? stdin : std::fopen(path.c_str(), "rb");
  if (!file) throw Error(std::string("cannot open: ") + std::strerror(errno), {path, 0});
  std::string contents;
  std::size_t used = 0;
  {
    struct stat st {};
    if (fstat(fileno(file), &st) == 0) {
      if (S_ISDIR(st.st_mode)) {
        if (!standard_input) std::fclose(file);
        throw Error("is a directory", {path, 0});
      }
      // One read for a regular file; the byte to spare sees its end.
      if (S_ISREG(st.st_mode)) contents.resize(static_cast<std::size_t>(st.st_size) + 1);
    }
  }
  ArrivingText text;
  try {
    for (;;) {
      if (used == contents.size()) contents.resize(std::max<std::size_t>(contents.size() * 2, 1u << 20));
      const std::size_t got = std::fread(contents.data() + used, 1, contents.size() - used, file);
      text.check(std::string_view(contents.data(), used + got), got == 0, name);
      used += got;
      if (got == 0) break;
    }
  } catch (const Error&) {
    if (!standard_input) std::fclose(file);
    throw;
  }
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  if (!standard_input) std::fclose(file);
  if (failed) throw Error(std::string("read error: ") + std::strerror(error), {name, 0});
  contents.resize(used);
  return read_dxf(contents, name, options);
}

}  // namespace tk::cad
