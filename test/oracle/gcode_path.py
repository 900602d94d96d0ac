#!/usr/bin/python3
"""Independent oracle for G-code programs (RS274/NGC subset).

Usage: gcode_path.py [--trace] FILE...

For every FILE prints one JSON object on its own line:

  {"file": basename, "final_x": mm, "final_y": mm, "final_z": mm,
   "feed_length_mm": ..., "rapid_length_mm": ..., "arc_count": n,
   "line_count": n, "blocks": n, "duration_s": ..., "dwell_s": ...}

Written from the RS274/NGC rules (Kramer et al., NIST IR 6556, and the
LinuxCNC G-code reference), not from any C++ code in this project, so that
it can serve as an independent check.  Standard library only.

Semantics (each one a deliberate choice; the C++ tool should match them):

* Start state: position (0,0,0), mm (G21), G90, G91.1 (incremental arc
  centres), G17, G94, no motion mode, feed rate undefined.
* A line is read in this order: '%' line?  block delete '/'?  then words.
  Whitespace (spaces, tabs) is ignored everywhere outside comments; letters
  are case-insensitive; '(...)' comments and ';' to end of line are dropped.
  - A line that is only '%' is not a block.  The first non-blank line may be
    '%'; any later '%' line ends the program (the rest is not read).
  - A line whose first non-blank character is '/' is skipped entirely
    (block delete switch on) and is not counted in "blocks".
  - M2 and M30 end the program after their block is executed; later lines
    are not read (RS274/NGC: "the interpreter does not even read them").
* "blocks" = lines (read before the end of the program) with at least one
  word other than the N line number.
* Words of one block take effect in the RS274/NGC order of execution:
  G93/G94, F, G4 dwell, G17/G18/G19, G20/G21 (G70/G71), G90/G91,
  G90.1/G91.1, motion, M2/M30.
* F (G94): units per minute in the length units in force after this
  block's G20/G21, converted to mm/min when read; a later G20/G21 does not
  change the physical feed.  F (G93): the block must take 60/F seconds.
* Motion mode (G0 G1 G2 G3) is modal; a block with axis words (X Y Z), or
  for G2/G3 with I/J/K words, and no motion G code moves in the last mode.
  G80 is ignored (it does not cancel the motion mode).
* line_count counts G1 blocks that move (axis words present, even if the
  length is zero); arc_count counts G2/G3 blocks.
* Arcs.  Plane coordinates (u, v) and helix axis w:
     G17: (X, Y), offsets (I, J), helix Z
     G18: (Z, X), offsets (K, I), helix Y   (looking from +Y)
     G19: (Y, Z), offsets (J, K), helix X
  G3 is counter-clockwise in the (u, v) order, G2 clockwise.
  Centre format: the centre is start+offset (G91.1) or the offset value
  itself (G90.1); the radius is the start radius; the swept angle is taken
  from the start and end angles about the centre, in the arc's direction,
  in (0, 2pi]; an end point equal to the start point (within 1e-9 mm)
  is a full circle.  Radius format: theta = 2*asin(chord/(2|R|)) for R>0,
  2pi minus that for R<0, radius |R|.  P (default 1) adds (P-1) full turns.
  Length = sqrt((r*theta)^2 + dw^2).
* G4 P is seconds.  Lengths and positions are reported in mm
  (inch values times 25.4).  duration_s sums length/feed for G1/G2/G3 in
  G94 and 60/F per block in G93; rapids and dwells are not included.

Anything unsupported or malformed is reported on stderr as
"FILE:LINE: warning: ..." and otherwise ignored; the JSON is still printed.
With --trace every move is also described on stderr.
"""

import json
import math
import os
import re
import sys

MM_PER_INCH = 25.4
FULL_CIRCLE_TOL_MM = 1e-9
RADIUS_WARN_MM = 0.005
TWO_PI = 2.0 * math.pi

WORD_RE = re.compile(r'([A-Z])([+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+))')

# G codes (value * 10, rounded) that are accepted and ignored quietly:
# cutter comp off, tool length offsets, work offsets, path control,
# canned-cycle cancel, spindle speed modes, canned-cycle retract modes,
# lathe diameter/radius modes.
QUIET_G = {400, 430, 431, 490, 540, 550, 560, 570, 580, 590, 591, 592, 593,
           610, 611, 640, 800, 960, 970, 980, 990, 70, 80}
QUIET_LETTERS = set('MSTHN')


class ProgramError(Exception):
    pass


def g_key(value):
    return int(round(value * 10.0))


def g_name(key):
    if key % 10 == 0:
        return 'G%d' % (key // 10)
    return 'G%d.%d' % (key // 10, key % 10)


def strip_comments(line, warn):
    """Return the line without comments and without whitespace, upper case."""
    out = []
    i = 0
    n = len(line)
    while i < n:
        c = line[i]
        if c == '(':
            j = line.find(')', i + 1)
            if j < 0:
                warn("unclosed '(' comment; rest of line ignored")
                break
            i = j + 1
            continue
        if c == ';':
            break
        if not c.isspace():
            out.append(c.upper())
        i += 1
    return ''.join(out)


def parse_words(text, warn):
    words = []
    pos = 0
    while pos < len(text):
        m = WORD_RE.match(text, pos)
        if not m:
            warn("cannot parse %r; rest of line ignored" % text[pos:])
            break
        words.append((m.group(1), float(m.group(2))))
        pos = m.end()
    return words


class Machine:
    def __init__(self, name, trace=False):
        self.name = name
        self.trace = trace
        self.lineno = 0
        self.pos = [0.0, 0.0, 0.0]
        self.inch = False
        self.absolute = True
        self.arc_absolute = False
        self.plane = 17
        self.inverse_time = False
        self.motion = None          # 0, 1, 2, 3 or None
        self.feed_mm_min = None     # G94 feed in mm/min
        self.feed_stale = False     # G93 -> G94 without a new F
        self.feed_length = 0.0
        self.rapid_length = 0.0
        self.arc_count = 0
        self.line_count = 0
        self.blocks = 0
        self.duration = 0.0
        self.dwell = 0.0
        self.max_radius_mismatch = 0.0
        self.radius_choice_spread = 0.0   # sum theta*|r_end - r_start|
        self.warnings = 0
        self.ended = False

    # -- reporting -------------------------------------------------------
    def warn(self, msg):
        self.warnings += 1
        sys.stderr.write('%s:%d: warning: %s\n' % (self.name, self.lineno, msg))

    def tr(self, msg):
        if self.trace:
            sys.stderr.write('%s:%d: %s\n' % (self.name, self.lineno, msg))

    def result(self):
        def r(v):
            v = round(v, 9)
            return 0.0 if v == 0 else v
        return {
            'file': self.name,
            'final_x': r(self.pos[0]),
            'final_y': r(self.pos[1]),
            'final_z': r(self.pos[2]),
            'feed_length_mm': r(self.feed_length),
            'rapid_length_mm': r(self.rapid_length),
            'arc_count': self.arc_count,
            'line_count': self.line_count,
            'blocks': self.blocks,
            'duration_s': r(self.duration),
            'dwell_s': r(self.dwell),
        }

    # -- one block -------------------------------------------------------
    def block(self, words):
        g_codes = []
        m_codes = []
        val = {}
        for letter, v in words:
            if letter == 'G':
                g_codes.append(g_key(v))
            elif letter == 'M':
                m_codes.append(int(round(v)))
            else:
                if letter in val and letter != 'N':
                    self.warn('%s word given twice; last one used' % letter)
                val[letter] = v
        if any(l != 'N' for l, _ in words):
            self.blocks += 1

        motion_g = None
        dwell = False
        for k in g_codes:
            if k in (0, 10, 20, 30):
                if motion_g is not None and motion_g != k // 10:
                    self.warn('two motion G codes in one block; last one used')
                motion_g = k // 10
            elif k == 40:
                dwell = True
            elif k in (170, 180, 190):
                pass
            elif k in (200, 210, 700, 710, 900, 910, 901, 911, 930, 940):
                pass
            elif k in QUIET_G:
                pass
            else:
                self.warn('unsupported %s ignored' % g_name(k))

        for letter in val:
            if letter in 'XYZIJKRFPGM' or letter in QUIET_LETTERS:
                continue
            self.warn('unsupported %s word ignored' % letter)
        # P outside G2/G3/G4 blocks belongs to M codes (M62 P1 ...), G64 etc.

        # 1. feed rate mode
        for k in g_codes:
            if k == 930:
                self.inverse_time = True
            elif k == 940:
                if self.inverse_time:
                    self.feed_stale = True
                self.inverse_time = False
        # units are needed to read F: look ahead at this block's G20/G21
        inch = self.inch
        for k in g_codes:
            if k in (200, 700):
                inch = True
            elif k in (210, 710):
                inch = False
        # 2. feed rate
        if 'F' in val and not self.inverse_time:
            self.feed_mm_min = val['F'] * (MM_PER_INCH if inch else 1.0)
            self.feed_stale = False
        # 3. dwell
        if dwell:
            p = val.get('P')
            if p is None:
                self.warn('G4 without P; no dwell')
            elif p < 0:
                self.warn('negative G4 P ignored')
            else:
                self.dwell += p
                self.tr('dwell %.6g s' % p)
        # 4. plane
        for k in g_codes:
            if k in (170, 180, 190):
                self.plane = k // 10
        # 5. units
        self.inch = inch
        # 6. distance modes
        for k in g_codes:
            if k == 900:
                self.absolute = True
            elif k == 910:
                self.absolute = False
            elif k == 901:
                self.arc_absolute = True
            elif k == 911:
                self.arc_absolute = False
        # 7. motion
        if motion_g is not None:
            self.motion = motion_g
        has_axis = any(a in val for a in 'XYZ')
        has_ijk = any(a in val for a in 'IJK')
        if has_axis or (self.motion in (2, 3) and (has_ijk or 'R' in val)):
            self.move(val)
        elif 'R' in val or has_ijk:
            self.warn('I/J/K/R words without an arc; ignored')
        # 8. program end
        if any(m in (2, 30) for m in m_codes):
            self.ended = True

    def target(self, val):
        u = MM_PER_INCH if self.inch else 1.0
        t = list(self.pos)
        for i, a in enumerate('XYZ'):
            if a in val:
                if self.absolute:
                    t[i] = val[a] * u
                else:
                    t[i] = self.pos[i] + val[a] * u
        return t

    def move(self, val):
        if self.motion is None:
            self.warn('axis words with no motion mode in force; position '
                      'updated, no length counted')
            self.pos = self.target(val)
            return
        end = self.target(val)
        start = self.pos
        if self.motion == 0:
            length = math.dist(start, end)
            self.rapid_length += length
            self.tr('G0 %s -> %s len %.9f' % (fmt(start), fmt(end), length))
        elif self.motion == 1:
            length = math.dist(start, end)
            self.line_count += 1
            self.feed_length += length
            self.add_time(length, val)
            self.tr('G1 %s -> %s len %.9f' % (fmt(start), fmt(end), length))
        else:
            length = self.arc(start, end, val)
            self.arc_count += 1
            self.feed_length += length
            self.add_time(length, val)
        self.pos = end

    def add_time(self, length, val):
        if self.inverse_time:
            f = val.get('F')
            if f is None:
                self.warn('G93 feed move without F word; no time counted')
            elif f <= 0:
                self.warn('G93 F <= 0; no time counted')
            else:
                self.duration += 60.0 / f
            return
        if self.feed_mm_min is None or self.feed_mm_min <= 0:
            if length > 0:
                self.warn('feed move with no (or zero) feed rate; '
                          'no time counted')
            return
        if self.feed_stale:
            self.warn('G94 after G93 without a new F; last G94 feed used')
            self.feed_stale = False
        self.duration += length / self.feed_mm_min * 60.0

    def arc(self, start, end, val):
        u = MM_PER_INCH if self.inch else 1.0
        if self.plane == 17:
            iu, iv, iw, lu, lv = 0, 1, 2, 'I', 'J'
        elif self.plane == 18:
            iu, iv, iw, lu, lv = 2, 0, 1, 'K', 'I'
        else:
            iu, iv, iw, lu, lv = 1, 2, 0, 'J', 'K'
        su, sv = start[iu], start[iv]
        eu, ev = end[iu], end[iv]
        dw = end[iw] - start[iw]
        ccw = self.motion == 3
        turns = 1
        if 'P' in val:
            p = val['P']
            turns = int(round(p))
            if abs(p - turns) > 1e-9 or turns < 1:
                self.warn('arc P must be a positive integer; P%g read as %d'
                          % (p, max(turns, 1)))
                turns = max(turns, 1)
        extra = TWO_PI * (turns - 1)
        # offsets of the other plane letter are not allowed (e.g. K in G17)
        for letter in 'IJK':
            if letter in val and letter not in (lu, lv):
                self.warn('%s word not in the arc plane G%d; ignored'
                          % (letter, self.plane))
        chord = math.hypot(eu - su, ev - sv)
        if 'R' in val and (lu in val or lv in val):
            self.warn('both R and centre offsets given; centre used')
        if lu in val or lv in val:
            ou = val.get(lu, 0.0) * u
            ov = val.get(lv, 0.0) * u
            if self.arc_absolute:
                if lu not in val or lv not in val:
                    self.warn('G90.1 arc with a missing centre word; 0 used')
                cu, cv = ou, ov
            else:
                cu, cv = su + ou, sv + ov
            r0 = math.hypot(su - cu, sv - cv)
            r1 = math.hypot(eu - cu, ev - cv)
            if r0 == 0.0:
                self.warn('arc of zero radius')
            mism = abs(r1 - r0)
            if mism > self.max_radius_mismatch:
                self.max_radius_mismatch = mism
            if mism > RADIUS_WARN_MM:
                self.warn('arc radius at start %.6f and at end %.6f differ '
                          'by %.6f mm' % (r0, r1, mism))
            if chord <= FULL_CIRCLE_TOL_MM:
                theta = TWO_PI
            else:
                a0 = math.atan2(sv - cv, su - cu)
                a1 = math.atan2(ev - cv, eu - cu)
                theta = ((a1 - a0) if ccw else (a0 - a1)) % TWO_PI
                if theta == 0.0:
                    theta = TWO_PI
            self.radius_choice_spread += theta * mism
            r = r0
            kind = 'centre (%.9f, %.9f) r_end %.9f' % (cu, cv, r1)
        elif 'R' in val:
            r = abs(val['R']) * u
            if chord <= FULL_CIRCLE_TOL_MM:
                self.warn('R-format arc with start == end is undefined; '
                          'taken as zero sweep')
                theta = 0.0
            else:
                s = chord / (2.0 * r) if r > 0 else float('inf')
                if s > 1.0:
                    if chord / 2.0 - r > RADIUS_WARN_MM:
                        self.warn('R%g too small for chord %.6f mm; taken as '
                                  'half circle' % (val['R'], chord))
                    s = 1.0
                theta = 2.0 * math.asin(s)
                if val['R'] < 0:
                    theta = TWO_PI - theta
            kind = 'R %.9f' % (val['R'] * u)
        else:
            self.warn('arc without I/J/K or R; counted as zero-length arc')
            self.tr('G%d no geometry' % self.motion)
            return 0.0
        theta += extra
        length = math.hypot(r * theta, dw)
        self.tr('G%d G%d %s -> %s %s r %.9f theta %.9f dw %.9f len %.9f'
                % (self.motion, self.plane, fmt(start), fmt(end), kind, r,
                   theta, dw, length))
        return length


def fmt(p):
    return '(%.6f %.6f %.6f)' % tuple(p)


def run_file(path, trace):
    name = os.path.basename(path)
    with open(path, 'r', encoding='utf-8', errors='replace') as fh:
        lines = fh.read().splitlines()
    m = Machine(name, trace)
    seen_content = False
    for lineno, raw in enumerate(lines, 1):
        m.lineno = lineno
        stripped = raw.strip()
        if not stripped:
            continue
        if stripped.startswith('%'):
            if seen_content:
                m.tr("'%' line ends the program")
                break
            seen_content = True
            continue
        seen_content = True
        if stripped.startswith('/'):
            m.tr('block deleted')
            continue
        text = strip_comments(raw, m.warn)
        if not text:
            continue
        words = parse_words(text, m.warn)
        if not words:
            continue
        m.block(words)
        if m.ended:
            break
    if trace:
        sys.stderr.write('%s: max arc radius mismatch %.9f mm; sum '
                         'theta*|r_end-r_start| %.9f mm; %d warnings\n'
                         % (name, m.max_radius_mismatch,
                            m.radius_choice_spread, m.warnings))
    return m.result()


def main(argv):
    args = argv[1:]
    trace = False
    if args and args[0] == '--trace':
        trace = True
        args = args[1:]
    if not args:
        sys.stderr.write('usage: gcode_path.py [--trace] FILE...\n')
        return 2
    status = 0
    for path in args:
        try:
            res = run_file(path, trace)
        except OSError as e:
            sys.stderr.write('%s: %s\n' % (path, e))
            status = 1
            continue
        sys.stdout.write(json.dumps(res) + '\n')
    return status


if __name__ == '__main__':
    sys.exit(main(sys.argv))
