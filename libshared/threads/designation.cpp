#include "threads/designation.hpp"

#include <fmt/format.h>

#include <cctype>

#include "io/error.hpp"
#include "io/record_fields.hpp"
#include "threads/iso261.hpp"

namespace tk::threads {
namespace {

// Beyond these the input is a typing or unit mistake: ISO 261 ends at 300 mm
// and ISO 965-1's tables at 355 mm.
constexpr double max_major_mm = 1000;
constexpr double max_pitch_mm = 50;
// Below a micrometre neither is a thread (and the canonical spelling would
// turn to exponents).
constexpr double min_length_mm = 0.001;

/// One spelling for the grammar below: the multiplication sign and '*' as
/// 'x', dashes and the minus sign as '-', the decimal comma (M1,6) as a
/// point. Spaces next to M, x, '-' or '/' go; a space between two other
/// characters separates parts as '-' does ("M8x1.25 6g", "M20x1.5-6g LH").
std::string normalised(std::string_view text) {
  std::string out;
  bool space = false;
  const auto is_joint = [](char c) { return c == 'x' || c == 'X' || c == '-' || c == '/' || c == 'M' || c == 'm'; };
  const auto put = [&](char c) {
    if (space && !out.empty() && !is_joint(out.back()) && !is_joint(c)) out += '-';
    space = false;
    out += c;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::string_view rest = text.substr(i);
    if (rest.starts_with("\xC3\x97")) {  // U+00D7 multiplication sign
      put('x');
      ++i;
    } else if (rest.starts_with("\xC2\xA0")) {  // U+00A0 no-break space
      space = true;
      ++i;
    } else if (rest.starts_with("\xE2\x80") && rest.size() > 2 && rest[2] >= '\x90' && rest[2] <= '\x95') {
      put('-');  // U+2010-2015 hyphens and dashes
      i += 2;
    } else if (rest.starts_with("\xE2\x88\x92")) {  // U+2212 minus sign
      put('-');
      i += 2;
    } else if (std::isspace(c)) {
      space = true;
    } else {
      put(c == '*' ? 'x' : c == ',' ? '.' : static_cast<char>(c));
    }
  }
  return out;
}

/// The designation as the user wrote it, for messages: control bytes as '?'.
std::string printable(std::string_view text) {
  std::string out;
  for (char c : text) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  return out;
}

/// The number of digits and points at the start of `rest`, read by the
/// toolkit's one number parser.
double take_number(std::string_view& rest, std::string_view what, std::string_view text) {
  std::size_t n = 0;
  while (n < rest.size() && (std::isdigit(static_cast<unsigned char>(rest[n])) || rest[n] == '.')) ++n;
  double value = 0;
  const io::NumberText parsed = n == 0 ? io::NumberText::not_a_number : io::parse_number_text(rest.substr(0, n), value);
  if (parsed == io::NumberText::out_of_range)
    throw Error(fmt::format("designation '{:.40}...': the {} is out of range", printable(text), what));
  if (parsed != io::NumberText::ok)
    throw Error(fmt::format("designation '{}': no {} where one was expected", printable(text), what));
  rest.remove_prefix(n);
  return value;
}

bool is_external_letter(char c) { return c == 'e' || c == 'f' || c == 'g' || c == 'h'; }
bool is_internal_letter(char c) { return c == 'G' || c == 'H'; }

ToleranceZone parse_zone(std::string_view part, std::string_view text) {
  const int grade = part[0] - '0';
  const char position = part[1];
  if (!is_external_letter(position) && !is_internal_letter(position))
    throw Error(
        fmt::format("designation '{}': '{}' is not a tolerance position of ISO 965-1 (e f g h for external "
                    "threads, G H for internal ones)",
                    printable(text), printable(std::string_view(&part[1], 1))));
  if (grade < 3 || grade > 9)
    throw Error(fmt::format("designation '{}': grade {} is outside ISO 965-1's grades 3 to 9", printable(text), grade));
  return {grade, position};
}

bool looks_like_class(std::string_view part) {
  return part.size() >= 2 && std::isdigit(static_cast<unsigned char>(part[0])) &&
         std::isalpha(static_cast<unsigned char>(part[1]));
}

ToleranceClass parse_class(std::string_view part, std::string_view text) {
  if (!(part.size() == 2 || part.size() == 4) || !looks_like_class(part) ||
      (part.size() == 4 && !looks_like_class(part.substr(2))))
    throw Error(fmt::format("designation '{}': '{}' is not a tolerance class like 6g, 5g6g or 6H", printable(text),
                            printable(part)));
  ToleranceClass result;
  result.pitch = parse_zone(part.substr(0, 2), text);
  result.crest = part.size() == 4 ? parse_zone(part.substr(2), text) : result.pitch;
  if (result.crest.position != result.pitch.position)
    throw Error(
        fmt::format("designation '{}': the crest diameter's position '{}' differs from the pitch diameter's "
                    "'{}' (ISO 965-1 gives one fundamental deviation per thread)",
                    printable(text), result.crest.position, result.pitch.position));
  return result;
}

void add_class(ThreadDesignation& out, const ToleranceClass& tolerance, std::string_view text) {
  std::optional<ToleranceClass>& slot = tolerance.external() ? out.external : out.internal;
  if (slot)
    throw Error(fmt::format("designation '{}': two {} tolerance classes", printable(text),
                            tolerance.external() ? "external" : "internal"));
  slot = tolerance;
}

}  // namespace

std::string ToleranceClass::text() const {
  if (pitch == crest) return fmt::format("{}{}", pitch.grade, pitch.position);
  return fmt::format("{}{}{}{}", pitch.grade, pitch.position, crest.grade, crest.position);
}

std::string ThreadDesignation::canonical() const {
  std::string out = fmt::format("M{}x{}", major_mm, pitch_mm);
  if (internal && external) out += fmt::format("-{}/{}", internal->text(), external->text());
  else if (internal || external) out += fmt::format("-{}", (internal ? internal : external)->text());
  if (engagement == Engagement::short_s) out += "-S";
  if (engagement == Engagement::long_l) out += "-L";
  if (left_hand) out += "-LH";
  return out;
}

ThreadDesignation parse_designation(std::string_view original) {
  const std::string text = normalised(original);
  if (text.empty()) throw Error("empty designation");
  std::string_view rest = text;
  if (rest.front() != 'M' && rest.front() != 'm')
    throw Error(fmt::format("designation '{}': an ISO metric thread starts with M (M30x2-6g)", printable(original)));
  rest.remove_prefix(1);
  ThreadDesignation out;
  out.major_mm = take_number(rest, "diameter", original);
  if (!(out.major_mm >= min_length_mm && out.major_mm <= max_major_mm))
    throw Error(fmt::format("designation '{}': diameter {} mm is outside [{}, {}]", printable(original), out.major_mm,
                            min_length_mm, max_major_mm));
  if (!rest.empty() && (rest.front() == 'x' || rest.front() == 'X')) {
    rest.remove_prefix(1);
    if (rest.starts_with("Ph") || rest.starts_with("PH") || rest.starts_with("ph"))
      throw Error(
          fmt::format("designation '{}': multi-start threads (Ph.. P..) are not supported", printable(original)));
    out.pitch_mm = take_number(rest, "pitch", original);
    if (!(out.pitch_mm >= min_length_mm && out.pitch_mm <= max_pitch_mm))
      throw Error(fmt::format("designation '{}': pitch {} mm is outside [{}, {}]", printable(original), out.pitch_mm,
                              min_length_mm, max_pitch_mm));
  } else {
    const std::optional<Iso261Size> size = iso261_size(out.major_mm);
    if (!size || size->coarse_pitch_mm <= 0)
      throw Error(fmt::format("designation '{}': ISO 261 has no coarse pitch for M{}; write the pitch (M{}x1.5)",
                              printable(original), out.major_mm, out.major_mm));
    out.pitch_mm = size->coarse_pitch_mm;
  }
  if (rest.starts_with("LH")) {
    out.left_hand = true;
    rest.remove_prefix(2);
  }
  bool engagement_seen = false;
  while (!rest.empty()) {
    if (rest.front() != '-')
      throw Error(fmt::format("designation '{}': unexpected '{}'", printable(original), printable(rest)));
    rest.remove_prefix(1);
    const std::string_view part = rest.substr(0, rest.find('-'));
    rest.remove_prefix(part.size());
    if (part == "LH" || part == "lh") {
      if (out.left_hand) throw Error(fmt::format("designation '{}': LH twice", printable(original)));
      out.left_hand = true;
    } else if (part.size() == 1 && std::string_view("SNLsnl").find(part[0]) != std::string_view::npos) {
      if (engagement_seen) throw Error(fmt::format("designation '{}': two lengths of engagement", printable(original)));
      engagement_seen = true;
      const char group = static_cast<char>(std::toupper(static_cast<unsigned char>(part[0])));
      out.engagement = group == 'S' ? Engagement::short_s : group == 'L' ? Engagement::long_l : Engagement::normal_n;
    } else if (const std::size_t slash = part.find('/'); slash != std::string_view::npos) {
      const ToleranceClass first = parse_class(part.substr(0, slash), original);
      const ToleranceClass second = parse_class(part.substr(slash + 1), original);
      if (first.external() == second.external())
        throw Error(fmt::format("designation '{}': a fit pairs an internal class with an external one (6H/6g)",
                                printable(original)));
      add_class(out, first, original);
      add_class(out, second, original);
    } else if (part.empty()) {
      throw Error(fmt::format("designation '{}': a '-' with nothing after it", printable(original)));
    } else if (part.size() > 2 && part.ends_with("LH") && looks_like_class(part)) {  // "6gLH"
      if (out.left_hand) throw Error(fmt::format("designation '{}': LH twice", printable(original)));
      out.left_hand = true;
      add_class(out, parse_class(part.substr(0, part.size() - 2), original), original);
    } else {
      add_class(out, parse_class(part, original), original);
    }
  }
  return out;
}

}  // namespace tk::threads
