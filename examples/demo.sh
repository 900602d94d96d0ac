#!/usr/bin/env bash
# The toolkit's main job, end to end. `make demo` builds and runs this.
# mrtest and riesel on real numbers from the prime-hunting literature, then
# sieve + mrtest, and at the end a search from scratch: sieve | mrtest |
# riesel finding and proving twin primes of 1,000 digits.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

echo "== The 'Prime Hunting' paper (Farkas et al.): 778965587811*2^36627-1 is prime,"
echo "   778965587811*2^36629-1 is not (BPSW with the k*2^n-1 special-form reduction):"
printf '778965587811*2^36627-1\n778965587811*2^36629-1\n' | mrtest -j 2
echo "   riesel proves both (Lucas-Lehmer-Riesel with P as LLR chooses it; res64 for a composite):"
printf '778965587811*2^36627-1\n778965587811*2^36629-1\n' | riesel -j 2
echo "   and again with the seed's own start, D = 13 (P = 11):"
printf '778965587811*2^36627-1\n' | riesel --start d13

echo
echo "== Mersenne exponents below 1300, found by testing every 2^p-1:"
seq 2 1300 | sed 's/^/2^/; s/$/-1/' | mrtest -j 2 --keep prime,probable --csv | cut -d, -f3 | tail -n +2 | tr '\n' ' '
echo

echo
echo "== A pipeline: candidates k*2^n+1 from a NewPGen-style sieve file, survivors kept:"
bash "$here/mrtest-newpgen.sh"

echo
echo "== The generalized sieve: twin candidates k*2^500-1, k*2^500+1 for k <= 10^5,"
echo "   sieved with the primes up to 10^7; mrtest keeps the survivors that are twin primes:"
survivors="$(sieve twin --n 500 --k 1:1e5 --pmax 1e7 -j 2)"
echo "   $(wc -l <<< "$survivors") of 100000 candidates survive the sieve"
mrtest -j 2 --keep prime,probable --csv <<< "$survivors" | cut -d, -f1-4

echo
echo "== Konczol & Gal's fuzzy line follower: three laps per t-norm on a simulated oval"
echo "   (the drastic t-norm stops the car; tnorm-bench(1)):"
tnorm-bench laps --tnorm all | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin):
    print("   %-14s completed %-5s %6.2f s  %s" % (r["tnorm"], r["completed"], r["total_s"], r["stop_reason"]))'
echo
echo "== Stryczek & Orawczak's adaptive feed: the original law against the modified one"
for variant in original modified; do
  fuzzyfeed --simulate --variant "$variant" | python3 -c '
import json, sys
r = json.load(sys.stdin)
print("   %-8s %.1f s against %.1f s at 100 %% override, override oscillation +-%.1f points" % (
    r["variant"], r["machining_time_s"], r["baseline_time_s"], r["override_oscillation_pct"]))'
done

echo
echo "== Rubio, Ibeas & Kollar's feed drive: sliding-mode control against PID, 10 s of 1 mm sin 3t"
echo "   under a micro-milling cut (smcsim(1)):"
for setting in "smc --Lambda 40" "smc --Lambda 400" "sta --alpha 200 --beta 200" "pid" "ppd"; do
  smcsim --controller $setting --summary | python3 -c '
import json, sys
r = json.load(sys.stdin)
print("   %-28s rms error %.5f mm, chattering %7.0f N/s" % (sys.argv[1], r["rms_error_mm"], r["chattering"]))' "$setting"
done

echo
echo "== Georgiev et al.'s sub-tuning of a lathe: 1000 simulated parts, 40 +- 0.02 mm, a wearing tool;"
echo "   the seed's trend test against the SPC charts (subtune(1)):"
subtune --simulate --arl-runs 500 | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin):
    arl0 = "" if r["arl0"] is None else ", in-control ARL %.0f parts" % r["arl0"]
    print("   %-9s %5.1f %% in tolerance, %3d corrections (%3d with no drift)%s" % (
        r["policy"], 100 * r["in_tolerance_share"], r["corrections"], r["false_alarms"], arl0))'

echo
echo "== Karker, Ando & Sudhan Raj's thread calculator: M30x2-6g to the middle of its tolerance zone"
echo "   and the threading passes (threadcalc(1)):"
threadcalc M30x2-6g | python3 -c '
import json, sys
r = json.load(sys.stdin)
print("   %s: d2 %.3f..%.3f, d %.3f..%.3f; Td2 %.4f, es %.4f; ap %.4f, chamfer %.4f x 45, %d passes" % (
    r["thread"], r["d2_min"], r["d2_max"], r["d_min"], r["d_max"], r["Td2"], r["es"], r["ap"], r["chamfer"], r["passes"]))'
threadcalc --gcode passes --length 40 M30x2-6g | gcode-pulse --summary | python3 -c '
import json, sys
r = json.load(sys.stdin)
print("   its G33 program, 40 mm long, runs %.1f s on gcode-pulse" % r["duration_s"])'

echo
echo "== The main job, a search from scratch: sieve | mrtest | riesel finds and proves"
echo "   twin primes k*2^3300-1, k*2^3300+1 of 1,000 digits (examples/search-twins.sh):"
bash "$here/search-twins.sh"
