/// @file gcode.hpp
/// @brief RS274/NGC (LinuxCNC/grbl dialect) subset: one source line is
/// lexed into words, and the interpreter keeps the modal state as LinuxCNC
/// does and turns each block into motions in millimetres, absolute
/// machine coordinates: the tool length offset (G43, G43.1) applies as in
/// LinuxCNC, work offsets do not (G54.. are reported, not executed: their
/// offsets would come from LinuxCNC's parameter file, zero here).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace tk::motion {

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kTwoPi = 2 * std::numbers::pi;

struct Vec3 {
  double x = 0, y = 0, z = 0;
  double& operator[](int axis) { return axis == 0 ? x : axis == 1 ? y : z; }
  double operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
};

/// One word: a letter (upper case) and its number as written.
struct GcodeWord {
  char letter = 0;
  double value = 0;
};

/// A lexed line. Comments are dropped (the text of "(MSG, ...)" is kept
/// in `message`); `block_delete` is set for a leading '/'; `percent` for
/// a '%' tape marker line. N (line number) words are checked and dropped.
struct GcodeLine {
  std::vector<GcodeWord> words;
  bool block_delete = false;
  bool percent = false;
  std::string message;
};

/// Lexes one line (a trailing CR of a CRLF file is blank space). Letters
/// are case-insensitive, words may be packed ("G00G21") and blanks may sit
/// anywhere inside a word, as LinuxCNC ignores them. Throws tk::Error (no
/// location: the caller adds file and line) for an unclosed or nested
/// comment, a letter without a number, a bad number ("1.2.3", "--1", a
/// number longer than 64 characters, inf, nan), a character that is no
/// G-code, control bytes (bytes 0x80 and above only inside comments, for
/// UTF-8 text), '#' parameters, '[' expressions and 'O' words (subroutines
/// and macros are not supported).
GcodeLine lex_gcode_line(std::string_view text);

enum class MotionKind : std::uint8_t { rapid, linear, arc, dwell };

/// One motion in mm and seconds. For arcs: `center` (the third axis
/// component equals start's), the plane's axes (`axis0`, `axis1`, normal
/// `axis2`: G17 = 0,1,2; G18 = 2,0,1; G19 = 1,2,0), `clockwise` seen from
/// the positive normal axis, `turns` extra full turns (P word, 0 for one
/// arc); the normal axis moves linearly from start to end (helix). An arc
/// whose end equals its start in the plane is a full circle. The end
/// radius may differ slightly from the start radius (LinuxCNC's tolerance):
/// the radius then changes linearly along the arc.
struct Motion {
  MotionKind kind = MotionKind::linear;
  Vec3 start, end;
  double feed = 0;  ///< mm/s along the path; 0 for rapid (the machine's maximum)
  /// G33, a `linear` motion whose `feed` is K times the spindle speed: the
  /// tool follows the spindle, so the machine must not slow it below that
  /// (PulseRun refuses a G33 faster than the machine can go) and starts it
  /// from rest after a motion that does not follow the spindle.
  bool spindle_synchronised = false;
  /// G93: `duration` is the block's time in s (`feed` is then the path
  /// length over that time, for information).
  bool inverse_time = false;
  double duration = 0;  ///< G93 blocks, and G4 dwells (s)
  Vec3 center;
  int axis0 = 0, axis1 = 1, axis2 = 2;
  bool clockwise = false;
  std::uint64_t turns = 0;
  std::size_t source_line = 0;  ///< 1-based line of the block
};

/// The angle an arc sweeps, in radians: (0, 2π] from start to end in its
/// direction (2π when the end equals the start in the plane), plus 2π per
/// extra turn.
double arc_sweep(const Motion& arc);

/// A dwell of `seconds` (> 0) where the machine stands; both interpreters' G4.
Motion dwell_at(const Vec3& position, double seconds, std::size_t source_line);

struct InterpreterOptions {
  bool lenient = false;  ///< skip unsupported motion words with a warning instead of failing
  /// Largest |coordinate| in mm accepted (beyond it the step counters could overflow).
  double max_coordinate_mm = 1e6;
  Vec3 start;  ///< where the machine is when the program starts (mm)
  /// Tool offsets for G43, mm (gcode-pulse --tool-table, tool_table.hpp).
  /// Without a table G43 of any tool but 0 is refused: its length is unknown.
  std::map<int, Vec3> tool_table;
  bool has_tool_table = false;
};

struct GcodeBlock;  // one line's words sorted out (gcode_block.hpp)

/// Modal state as LinuxCNC keeps it, and what it did not execute.
///
/// Lathe work follows LinuxCNC's rules:
/// - G33 X- Y- Z- K- (spindle-synchronised motion, threading) is a motion
///   mode like G1 and stays in force. K, in the program's units, is the
///   distance per spindle revolution along the line the axis words draw
///   (LinuxCNC's drive line: on a taper, Z advances less than K per turn),
///   and every G33 block needs its own K (K is not modal). No spindle turns
///   here, so the line is timed at K times the spindle speed S (rpm, the
///   last S word, not scaled by G20) along the path; F plays no part (an F
///   on a G33 line is an error, as in LinuxCNC, and the modal F stays for
///   later G1-G3). The feed mode (G93/G94) does not apply to it either.
///   The spindle must be turning (M3 or M4 since the last M5) at a positive
///   S, and not in G96, whose S is a surface speed: the rpm would be
///   unknown. A G33 line must have an axis word.
/// - G7 makes X words diameters: the machine's X is half the word,
///   absolute or incremental (LinuxCNC halves the number as it reads it);
///   arc centre words (I) and R stay radii, as LinuxCNC leaves them. G8,
///   radius mode, is the default. position() and the motions are machine
///   coordinates, so X there is always a radius.
///
/// Choices where the dialects differ or LinuxCNC leaves it to the operator:
/// - lines starting with '/' are skipped (the block delete switch is on);
/// - lines after M2/M30 are ignored (LinuxCNC stops reading there);
/// - F is read in the units in effect after the line's own G20/G21, and a
///   feed rate keeps its speed across later unit changes; leaving G93 for
///   G94 clears it (a G93 F is a time, not a speed);
/// - G70/G71 (Mach3, older Fanuc) are inch/mm like G20/G21;
/// - G80 on a line with G0-G3 ("G00 G90 G80", Mach3/Fanuc, where G80 only
///   cancels canned cycles) is ignored; alone it cancels the motion mode;
/// - the startup motion mode is G0 (grbl, Mach3), not LinuxCNC's G80;
/// - an M code that takes P (M62-M66...) owns the line's P, so an arc on
///   that line makes one turn;
/// - unknown G codes are errors even when lenient (their effect is unknown).
class GcodeInterpreter {
 public:
  explicit GcodeInterpreter(InterpreterOptions options = {});

  /// Executes one lexed line (source line `line_number`, 1-based),
  /// appending its motions to `out` in order. Throws tk::Error (no
  /// location; the interpreter's state is then unspecified) on: two words
  /// of one modal group, a letter twice, an unknown G code, a word nothing
  /// on the line uses (R with G1), G1/G2/G3 without a feed rate (F0 or
  /// none yet in G94; no F on the line in G93), a negative F, an arc with
  /// centre words of the wrong plane, with neither or both of R and centre
  /// words, with a zero radius or with a centre whose end radius differs
  /// from the start radius by more than 0.5 mm, or by more than 0.005 mm
  /// and 0.1% (LinuxCNC's rule; inches: 0.05 in, 0.0005 in), an R arc
  /// whose chord exceeds 2R, axis words with no motion mode (after G80),
  /// a coordinate beyond max_coordinate_mm, a negative S, G43 of a tool
  /// other than 0 without a tool table (lenient: skipped) or of a tool
  /// not in it, G53 in G91 or outside G0/G1, and a G33
  /// without axis words, without K or with K <= 0, with an F word, with the
  /// spindle stopped, at S0 or in G96. Words it cannot honour (G41/G42
  /// cutter compensation, G33.1 rigid tapping, G76 threading, canned cycles
  /// G73 G81-G89, G38.x probing, G28/G30 homing, G92 offsets, G10, G43.2, G5
  /// splines, G95, A B C U V W axes...) are errors too unless
  /// options.lenient, which skips the word with a warning through `warn`,
  /// and the line's motion with it when the word owns the axis words (a
  /// motion mode such as G81, which also skips later lines in that mode,
  /// or G28, G92...).
  void execute(const GcodeLine& line, std::size_t line_number, std::vector<Motion>& out);

  /// Warnings (lenient skips) go here; default: dropped.
  void on_warning(std::function<void(const std::string&)> warn) { warn_ = std::move(warn); }

  const Vec3& position() const { return position_; }
  /// Words with no effect on the tool path or its timing, with how many
  /// times they came: M codes other than M2/M30 ("M3", "M6", "M62": M03
  /// counts as "M3"; M3, M4 and M5 only decide whether G33 may run; T, M6
  /// and M61 choose the tool G43 measures), T, D, H other than G43's, and
  /// G40 G54-G59.3 G61 G61.1 G64 G96 G97 G98 G99 (and G80 when ignored). Argument words of these (M62 P, G64 P Q) are
  /// not counted. Modal codes and values that act (G7, G17, G20, G90..., F, and S, which times G33) are not here.
  const std::map<std::string, std::uint64_t>& unused_words() const { return unused_; }
  /// Lines executed that hold a word other than N (blank, comment-only,
  /// '%' and block-deleted lines do not count).
  std::uint64_t blocks() const { return blocks_; }
  bool program_ended() const { return ended_; }  ///< M2 or M30 seen

 private:
  bool skip_unsupported(GcodeBlock& block);
  void record_unused(GcodeBlock& block);
  void set_modes(GcodeBlock& block);
  void set_spindle(GcodeBlock& block);
  void set_tool_offset(GcodeBlock& block);
  void move(GcodeBlock& block, bool skip_motion, std::size_t line_number, std::vector<Motion>& out);
  double synchronised_speed(GcodeBlock& block) const;
  void arc(GcodeBlock& block, Motion& motion) const;
  void warn(const std::string& message) const;
  double unit() const { return inches_ ? kMmPerInch : 1.0; }  ///< mm per program unit

  InterpreterOptions options_;
  std::function<void(const std::string&)> warn_;
  Vec3 position_;
  /// 0 G0, 1 G1, 2 G2, 3 G3, 33 G33, -1 none (G80), -2 an unsupported
  /// mode that lenient skipped (`skipped_mode_` names it).
  int motion_mode_ = 0;
  std::string skipped_mode_;
  int plane_ = 17;
  bool inches_ = false, incremental_ = false, arc_incremental_ = true, inverse_time_ = false;
  bool diameter_mode_ = false;           ///< G7: X words are diameters
  double feed_ = 0;                      ///< mm/min (converted from in/min)
  double spindle_speed_ = 0;             ///< the last S word: rpm, or a surface speed under G96
  bool spindle_turning_ = false;         ///< M3 or M4 since the last M5
  bool constant_surface_speed_ = false;  ///< G96
  std::map<std::string, std::uint64_t> unused_;
  std::uint64_t blocks_ = 0;
  bool ended_ = false;
  int selected_tool_ = 0, loaded_tool_ = 0;  ///< T; M6 or M61 Q
  Vec3 tool_offset_;                         ///< added to absolute coordinates (G43, G43.1; G49 clears it)
};

}  // namespace tk::motion
