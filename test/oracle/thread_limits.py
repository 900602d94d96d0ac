#!/usr/bin/env python3
"""Oracle for threadcalc: its limits of size against the published ISO 965-2
tables in test/fixtures/threads/iso965-2_limits.csv (values read from
catalogues and handbooks, never computed; see the fixture's README).

For each row and each member the fixture prints (external 6g/6h, internal
6H), threadcalc runs on the designation and must give:
  - every published limit within 0.5 um (the tables round to 1 um);
  - the tolerances and the deviation exactly, in whole micrometres, as the
    published limits imply them: Td = d max - d min, Td2 = d2 max - d2 min,
    es = d max - d, TD1 = D1 max - D1 min, TD2 = D2 max - D2 min,
    EI = D1 min - D1 with D1 = d - 1.082532 P rounded to 1 um (ISO 724);
  - no value computed from a formula (every row is an ISO 261 size, which
    ISO 965-1's tables cover), and the pitch series the designation implies.

usage: thread_limits.py THREADCALC FIXTURE  -> prints a summary; exit 1 on a mismatch
"""
import csv
import json
import subprocess
import sys

EXTERNAL = ["d_max", "d_min", "d2_max", "d2_min", "d3_max"]
INTERNAL = ["D1_min", "D1_max", "D2_min", "D2_max"]


def number(text):
    return float(text) if text.strip() else None


def um(mm):
    return round(mm * 1000)


def main(threadcalc, fixture):
    rows = list(csv.DictReader(open(fixture, newline="")))
    jobs = []  # (row, kind, designation)
    for row in rows:
        if any(number(row[k]) is not None for k in EXTERNAL):
            jobs.append((row, "external", f'{row["designation"]}-{row["external_class"]}'))
        if any(number(row[k]) is not None for k in INTERNAL):
            jobs.append((row, "internal", f'{row["designation"]}-{row["internal_class"]}'))
    request = "designation\n" + "".join(d + "\n" for _, _, d in jobs)
    run = subprocess.run([threadcalc, "--decimals", "9", "-q"], input=request, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"threadcalc failed: {run.stderr}")
    results = [json.loads(line) for line in run.stdout.splitlines()]
    if len(results) != len(jobs):
        sys.exit(f"{len(jobs)} designations in, {len(results)} records out")

    failures, compared, exact = [], 0, 0

    def expect(ok, what):
        if not ok:
            failures.append(what)

    for (row, kind, designation), r in zip(jobs, results):
        name = f"{designation} ({row['source']})"
        expect(r["kind"] == kind, f"{name}: kind {r['kind']}")
        expect(r["computed"] == "", f"{name}: computed {r['computed']}")
        series = "fine" if "x" in row["designation"] else "coarse"
        expect(r["pitch_series"] == series, f"{name}: pitch series {r['pitch_series']}, want {series}")
        d, pitch = r["d"], r["P"]
        expect(abs(d - float(row["designation"][1:].split("x")[0])) < 1e-12, f"{name}: d {d}")
        for key in EXTERNAL if kind == "external" else INTERNAL:
            published = number(row[key])
            if published is None:
                continue
            compared += 1
            expect(abs(r[key] - published) <= 0.0005 + 1e-9, f"{name}: {key} {r[key]:.6f}, published {published:.3f}")
        p = {k: number(row[k]) for k in EXTERNAL + INTERNAL}
        if kind == "external":
            checks = []
            if p["d_max"] is not None and p["d_min"] is not None:
                checks.append(("Td", um(p["d_max"] - p["d_min"])))
            if p["d2_max"] is not None and p["d2_min"] is not None:
                checks.append(("Td2", um(p["d2_max"] - p["d2_min"])))
            if p["d_max"] is not None:
                checks.append(("es", um(p["d_max"] - d)))
        else:
            checks = []
            if p["D1_max"] is not None and p["D1_min"] is not None:
                checks.append(("TD1", um(p["D1_max"] - p["D1_min"])))
            if p["D2_max"] is not None and p["D2_min"] is not None:
                checks.append(("TD2", um(p["D2_max"] - p["D2_min"])))
            if p["D1_min"] is not None:
                checks.append(("EI", um(p["D1_min"] - round(d - 1.082532 * pitch, 3))))
        for key, want in checks:
            exact += 1
            expect(um(r[key]) == want, f"{name}: {key} {um(r[key])} um, published limits give {want} um")

    for failure in failures:
        print("MISMATCH", failure)
    external = sum(1 for _, k, _ in jobs if k == "external")
    print(f"{len(rows)} sizes, {external} external and {len(jobs) - external} internal members; "
          f"{compared} published limits within 0.5 um, {exact} tolerances exact; {len(failures)} mismatches")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
