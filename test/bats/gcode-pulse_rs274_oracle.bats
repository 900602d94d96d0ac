#!/usr/bin/env bats
# LinuxCNC's own interpreter as the oracle. rs274 (Debian's linuxcnc-uspace)
# prints the canonical machining commands of a program; test/oracle/
# rs274_canon.py maps them to machine positions and path lengths on its own
# (program coordinates + G92, XY rotation, G5x and tool offsets).
#  - gcode-pulse --canon steps whatever rs274 finishes on three axes and
#    ends where rs274 puts the machine;
#  - where our own interpreter runs a program too, both paths agree;
#  - G43, G43.1, G49 and G53 end where LinuxCNC puts them.

bats_require_minimum_version 1.5.0

NCFILES=/usr/share/linuxcnc/ncfiles

# canon PROGRAM > canonical commands: rs274 (test_helper's rs274_g) with the
# test tool table and the block delete switch on (-b), as gcode-pulse reads
# '/' lines; the stream's end, not rs274's exit status, tells an error.
canon() {
  rs274_g "$1" -b -t "$TOOLS_INCH" 2> /dev/null || true
}

setup_file() {
  load test_helper
  command -v rs274 > /dev/null || return 0
  TOOLS_INCH="$BATS_TEST_DIRNAME/../fixtures/gcode/linuxcnc/rs274_tools_inch.tbl"
  # LinuxCNC's examples through rs274 once, for the tests that use them.
  mkdir -p "$BATS_FILE_TMPDIR/ncfiles"
  local program
  for program in "$NCFILES"/*.ngc; do
    [ -e "$program" ] && canon "$program" > "$BATS_FILE_TMPDIR/ncfiles/$(basename "$program" .ngc).canon"
  done
}

setup() {
  load test_helper
  command -v rs274 > /dev/null || skip "rs274 (linuxcnc-uspace) is not installed"
  cd "$BATS_TEST_TMPDIR"
  ORACLE="$TOOLKIT_ROOT/test/oracle/rs274_canon.py"
  TOOLS_INCH="$FIXTURES/gcode/linuxcnc/rs274_tools_inch.tbl"
  TOOLS_MM="$FIXTURES/gcode/linuxcnc/rs274_tools_mm.tbl"
}

# within_a_step_each ROWS: each row of the file ROWS is
# "LABEL<tab>path|ends<tab>ORACLE_JSON<tab>SUMMARY_JSON": final positions
# within a step (the default 200, 200, 400 steps/mm) plus rs274's 4-decimal
# printing; with "path", the path lengths within a step too. One Python for
# all rows; prints each row that differs, fails if any does (or ROWS is empty).
within_a_step_each() {
  py '
import json, sys
step = {"x": 1/200, "y": 1/200, "z": 1/400}
rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1]) if line.strip()]
failed = 0
for label, mode, oracle, summary in rows:
    try:
        o, s = json.loads(oracle), json.loads(summary)
    except ValueError:
        failed += 1
        print("%s: no summary to compare\n rs274: %s\n ours: %r" % (label, oracle, summary))
        continue
    bad = [a for a in "xyz" if abs(o["final_" + a] - s["final_" + a]) > step[a] + 0.0001 * 25.4]
    if mode == "path" and abs(o["path_mm"] - s["path_mm"]) > 1/200:
        bad.append("path %.6f vs %.6f" % (o["path_mm"], s["path_mm"]))
    if bad:
        failed += 1
        print("%s differ: %s\n rs274: %s\n ours: %s" % (label, bad, oracle, summary))
print(len(rows), "compared,", failed, "differ")
sys.exit(1 if failed or not rows else 0)
' "$1"
}

# pair LABEL MODE ORACLE_JSON SUMMARY_JSON >> ROWS: one row for within_a_step_each.
pair() { printf '%s\t%s\t%s\t%s\n' "$@"; }

@test "every shipped LinuxCNC example rs274 finishes on 3 axes: gcode-pulse --canon ends where rs274 puts the machine" {
  [ -d "$NCFILES" ] || skip "LinuxCNC's examples are not installed"
  local stepped=0 refused=0 i stream oracle summary streams oracles
  streams=("$BATS_FILE_TMPDIR"/ncfiles/*.canon)
  mapfile -t oracles < <(/usr/bin/python3 "$ORACLE" "${streams[@]}")
  [ "${#oracles[@]}" -eq "${#streams[@]}" ]
  : > rows.tsv
  for i in "${!streams[@]}"; do
    stream=${streams[i]} oracle=${oracles[i]}
    case "$oracle" in
      *'"status": "incomplete"'*) continue ;;  # rs274 itself stopped on an error
      *'"status": "extra_axes"'*)
        run -1 --separate-stderr gcode-pulse --canon --summary "$stream"
        [[ "$stderr" == *"gcode-pulse steps X, Y and Z only"* ]] || { echo "$stream: $stderr"; false; }
        refused=$((refused + 1)) ;;
      *'"status": "nurbs"'*)
        run -1 --separate-stderr gcode-pulse --canon --summary "$stream"
        [[ "$stderr" == *"NURBS_FEED"* ]] || { echo "$stream: $stderr"; false; }
        refused=$((refused + 1)) ;;
      *)
        summary=$(gcode-pulse --canon --summary "$stream") || { echo "$stream failed"; false; }
        pair "$stream" path "$oracle" "$summary" >> rows.tsv
        stepped=$((stepped + 1)) ;;
    esac
  done
  within_a_step_each rows.tsv
  echo "stepped $stepped, refused $refused (rotary axes, splines)"
  # 48 of the 56 examples of LinuxCNC 2.9 finish in rs274 with this tool
  # table; 3 of those move A or B or use splines.
  [ "$stepped" -ge 45 ]
}

@test "our interpreter and the canonical path agree on the corpus, the fixtures and LinuxCNC's examples" {
  local compared=0 i program stream summary streams=() candidates=() ours=() oracles path
  local programs=("$FIXTURES"/gcode/*.ngc "$FIXTURES"/gcode/linuxcnc/*.ngc)
  [ -d "$TOOLKIT_ROOT/../shared/corpus/gcode" ] && programs+=("$TOOLKIT_ROOT"/../shared/corpus/gcode/*)
  [ -d "$NCFILES" ] && programs+=("$NCFILES"/*.ngc)
  for program in "${programs[@]}"; do
    summary=$(gcode-pulse --summary --tool-table "$TOOLS_MM" "$program" 2> /dev/null) || continue
    stream="$BATS_FILE_TMPDIR/ncfiles/$(basename "$program" .ngc).canon"
    if [[ "$program" != "$NCFILES"/* ]]; then
      # rs274 wants a program end; grbl-style files often have none.
      { cat "$program"; echo; echo M2; } > with_end.ngc
      stream="$PWD/run${#streams[@]}.canon"
      canon "$PWD/with_end.ngc" > "$stream"
    fi
    candidates+=("$program") streams+=("$stream") ours+=("$summary")
  done
  mapfile -t oracles < <(/usr/bin/python3 "$ORACLE" "${streams[@]}")
  [ "${#oracles[@]}" -eq "${#streams[@]}" ]
  : > rows.tsv
  for i in "${!streams[@]}"; do
    program=${candidates[i]}
    [[ "${oracles[i]}" == *'"status": "ok"'* ]] || continue  # a dialect LinuxCNC reads otherwise (Mach3's G71)
    summary=$(gcode-pulse --canon --summary "${streams[i]}")
    # rs274 alone re-reads the position after a tool change without the new
    # tool offset, so a G43 on an M6's line moves Z on the next move there
    # (LinuxCNC does not, nor do we): compare the ends only.
    path=path
    grep -qiE 'M0*6.*G43|G43.*M0*6' "$program" && path=ends
    pair "$program (our interpreter)" "$path" "${oracles[i]}" "${ours[i]}" >> rows.tsv
    pair "$program (--canon)" path "${oracles[i]}" "$summary" >> rows.tsv
    compared=$((compared + 1))
  done
  within_a_step_each rows.tsv
  echo "compared $compared programs"
  [ "$compared" -ge 20 ]
}

@test "G43, G43 H, G43.1, G49 and G53 put the machine where LinuxCNC does, after every line" {
  local program="$FIXTURES/gcode/linuxcnc/tool_length.ngc" lines n i oracles streams=()
  lines=$(grep -c . "$program")
  : > rows.tsv
  for n in $(seq 3 $((lines - 1))); do
    { head -n "$n" "$program"; echo M2; } > "prefix$n.ngc"
    canon "$PWD/prefix$n.ngc" > "run$n.canon"
    streams+=("run$n.canon")
  done
  mapfile -t oracles < <(/usr/bin/python3 "$ORACLE" "${streams[@]}")
  [ "${#oracles[@]}" -eq "${#streams[@]}" ]
  for i in "${!streams[@]}"; do
    n=$((i + 3))
    [[ "${oracles[i]}" == *'"status": "ok"'* ]] || { echo "rs274 did not finish line $n"; cat "run$n.canon"; false; }
    pair "after line $n (our interpreter)" path "${oracles[i]}" \
      "$(gcode-pulse --summary --tool-table "$TOOLS_MM" "prefix$n.ngc")" >> rows.tsv
    pair "after line $n (--canon)" path "${oracles[i]}" "$(gcode-pulse --canon --summary "run$n.canon")" >> rows.tsv
  done
  within_a_step_each rows.tsv
}

@test "G43 without a tool table is refused, not ignored; --lenient skips it with a warning" {
  run -1 --separate-stderr gcode-pulse --summary "$FIXTURES/gcode/linuxcnc/tool_length.ngc"
  [[ "$stderr" =~ tool_length\.ngc:5:\ G43.*tool\ 3.*--tool-table ]] || { echo "$stderr"; false; }
  run -0 --separate-stderr gcode-pulse --summary --lenient "$FIXTURES/gcode/linuxcnc/tool_length.ngc"
  [[ "$stderr" == *"skipped G43"* ]]
  printf 'G21\nT0 M6 G43\nG0 X1\nM2\n' > tool0.ngc
  run -0 gcode-pulse --summary tool0.ngc  # tool 0 (none) has no length to know
  run -1 --separate-stderr gcode-pulse --summary --tool-table "$TOOLS_MM" <(printf 'G43 H42\nM2\n')
  [[ "$stderr" == *"tool 42 is not in the tool table"* ]]
}

@test "a canonical stream rs274 did not finish is an error after its pulses; lines that are no command are refused" {
  printf 'G21 G1 X1 F100\nG1 X2 Y [1 +\nM2\n' > broken.ngc
  canon "$PWD/broken.ngc" > run.canon
  run -1 --separate-stderr gcode-pulse --canon run.canon
  [[ "$stderr" == *"without PROGRAM_END()"* ]] || { echo "$stderr"; false; }
  # the move before the error was stepped: 200 steps of X
  [ "$(grep -c '^{' <<< "$output")" -eq 200 ]
  printf '    1 N..... STRAIGHT_FEED(1.0, 2.0)\n' > short.canon
  run -1 --separate-stderr gcode-pulse --canon short.canon
  [[ "$stderr" =~ short\.canon:1:\ STRAIGHT_FEED\ takes\ 6\ or\ 9\ arguments ]]
  printf 'G1 X1 F100\n' > gcode.canon
  run -1 --separate-stderr gcode-pulse --canon gcode.canon
  [[ "$stderr" == *"gcode.canon:1: not a canonical command"* ]]
}

@test "examples/gcode-pulse-linuxcnc.sh steps LinuxCNC's programs through rs274" {
  [ -d "$NCFILES" ] || skip "LinuxCNC's examples are not installed"
  run -0 bash "$TOOLKIT_ROOT/examples/gcode-pulse-linuxcnc.sh"
  refute_output --partial "not finished"
  # polar.ngc (polar coordinates, canned cycles) ends 2 inches out on X, 0.2 inch up
  assert_line --regexp '^polar\.ngc +no +50\.8000 +0\.0000 +5\.0800 '
  [ "$(grep -cE '^[a-z-]+\.ngc +(yes|no) ' <<< "$output")" -eq 6 ]
}
