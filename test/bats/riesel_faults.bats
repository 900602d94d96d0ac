#!/usr/bin/env bats
# Fault injection for riesel --state: kills at random moments, damaged
# journal lines and crafted checkpoints. Verdicts are held against PARI/GP's
# isprime, never against riesel's own earlier output.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  command -v gp > /dev/null || skip "PARI/GP (pari-gp) is not installed"
}

# candidates COUNT SEED > in.txt: k*2^n+-1 with k odd below 2^n, n from 40 to
# 130, a quarter of them prime (chosen with gp), in a shuffled order.
candidates() {
  python3 - "$1" "$2" <<'PY' > pool.txt
import random, sys
rng = random.Random(int(sys.argv[2]))
seen = set()
while len(seen) < 12 * int(sys.argv[1]):
    n = rng.randrange(40, 131)
    k = rng.randrange(1, 4000) | 1
    seen.add(f"{k}*2^{n}{rng.choice(['-1', '+1'])}")
print("\n".join(sorted(seen)))
PY
  gp_verdicts < pool.txt > pool.verdicts
  python3 - "$1" "$2" <<'PY'
import random, sys
count, rng = int(sys.argv[1]), random.Random(int(sys.argv[2]))
pool = list(zip(open("pool.txt").read().split(), open("pool.verdicts").read().split()))
primes = [n for n, v in pool if v == "prime"][: count // 4]
composites = [n for n, v in pool if v == "composite"][: count - len(primes)]
chosen = primes + composites
rng.shuffle(chosen)
print("\n".join(chosen))
PY
}

# gp_verdicts < numbers: "prime" or "composite" per line, by PARI's isprime.
gp_verdicts() {
  sed -E 's/.*/print(if(isprime(&),"prime","composite"))/' | gp -q -f
}

# lresults_verdicts FILE: "NUMBER prime|composite" per lresults.txt line.
lresults_verdicts() {
  sed -E 's/^([^ ]+) is prime!.*/\1 prime/; s/^([^ ]+) is not prime\..*/\1 composite/' "$1"
}

# count_journal: sets journaled to the lines of st/journal.tsv so far. Bash
# builtins only (as the pause in the polling loop): under load, starting a
# process takes longer than riesel takes to journal several records.
count_journal() {
  journaled=0
  if [ -f st/journal.tsv ]; then
    mapfile -t journal_text < st/journal.tsv
    journaled=${#journal_text[@]}
  fi
}

# paced_input: in.txt's lines with a pause of ~2 ms after each (bash only).
paced_input() {
  local line
  while IFS= read -r line; do
    printf '%s\n' "$line" || return 0
    read -r -t 0.002 -u "$never" || true
  done < in.txt
}

@test "kill -9 and SIGTERM at random moments, then a run to the end: every number logged once, journal and output agree, PARI's verdicts" {
  candidates 400 21 > in.txt
  paste -d' ' in.txt <(gp_verdicts < in.txt) | sort > want.txt
  grep -q ' prime$' want.txt && grep -q ' composite$' want.txt
  RANDOM=21
  kills=0
  mkfifo never
  exec {never}<> never  # read -t on it: a pause without starting a process
  # Until 16 kills have landed in a working run (at most 40 rounds).
  for round in $(seq 1 40); do
    [ "$kills" -lt 16 ] || break
    count_journal
    target=$((journaled + 1 + RANDOM % 8))
    # The records come paced, one per ~2 ms: where syncs cost nothing (a
    # tmpfs /tmp) a whole run otherwise ends before a kill can land.
    paced_input | riesel -j $((1 + round % 2)) --state st > "out.$round" 2> "err.$round" 3>&- &
    pid=$!
    # Once 1 to 8 more records are journaled, and 1 to 9 ms later: the kill
    # lands while the run works (in a proof, an append, a sync).
    while kill -0 "$pid" 2> /dev/null && [ "$journaled" -lt "$target" ]; do
      read -r -t 0.001 -u "$never" || true
      count_journal
    done
    read -r -t "0.00$((1 + RANDOM % 9))" -u "$never" || true
    signal=KILL
    [ $((round % 4)) -eq 0 ] && signal=TERM
    kill -"$signal" "$pid" 2> /dev/null && kills=$((kills + 1))
    status=0
    wait "$pid" || status=$?
    # Killed (137, 143), or finished before the signal (0); nothing else.
    [[ " 0 137 143 " == *" $status "* ]] || { echo "round $round: exit $status"; cat "err.$round"; false; }
  done
  count_journal
  echo "kills: $kills, records journaled before the last run: $journaled of 400"
  [ "$kills" -ge 15 ]
  # The run to the end.
  run --separate-stderr timeout 120 riesel --state st in.txt
  assert_success
  echo "$output" > final.out
  # Output: one record per input line, in order, with PARI's verdict.
  run python3 -c '
import json, sys
want = dict(line.split() for line in open("want.txt"))
numbers = open("in.txt").read().split()
records = [json.loads(line) for line in open("final.out")]
assert len(records) == len(numbers), (len(records), len(numbers))
for number, record in zip(numbers, records):
    assert record["verdict"] == want[number], (number, record)
print("ok")'
  assert_output ok
  # lresults.txt: each number exactly once, with PARI's verdict.
  lresults_verdicts st/lresults.txt | sort > logged.txt
  run uniq -d logged.txt
  assert_output ""
  run cmp logged.txt want.txt
  assert_success
  # The journal: one line per number with PARI's verdict, and its lresults.txt
  # lines in order are the file's lines.
  run python3 -c '
import json
want = dict(line.split() for line in open("want.txt"))
lines = open("st/journal.tsv").read().split("\n")
assert lines[-1] == ""
fields = [line.split("\t") for line in lines[:-1]]
outputs = [json.loads(f[1]) for f in fields]
assert len(outputs) == len(want), (len(outputs), len(want))
for key, output in zip(fields, outputs):
    number = json.loads(key[0].split(" ", 1)[1])
    number = "%d*2^%d%+d" % (number["k"], number["n"], number["c"])
    assert output["verdict"] == want[number], (number, output)
logged = [line for f in fields for line in json.loads(f[3])]
assert logged == open("st/lresults.txt").read().splitlines(), "journal and lresults.txt differ"
print("ok")'
  assert_output ok
}

@test "a run killed after journaling a record but before lresults.txt: the next start writes its lines, once" {
  printf '%s\n' '{"k":3,"b":2,"n":391,"c":-1}' '{"k":5,"b":2,"n":100,"c":-1}' '{"k":3,"n":2,"form":"cc1","length":3}' > in.txt
  riesel --state st in.txt > /dev/null
  cp st/lresults.txt whole.txt
  # The form's three members, then all of its lines but the first, then half a line.
  size=$(stat -c %s whole.txt)
  last3=$(tail -n 3 whole.txt | wc -c)
  last2=$(tail -n 2 whole.txt | wc -c)
  for cut in "$last3" "$last2" 20; do
    truncate -s $((size - cut)) st/lresults.txt
    run --separate-stderr riesel --state st in.txt
    assert_success
    run cmp st/lresults.txt whole.txt
    assert_success
  done
  # Against PARI: 3*2^391-1 prime, 5*2^100-1 composite, 5, 11, 23 prime.
  run python3 -c 'print(open("whole.txt").read())'
  assert_line --index 0 --regexp '^3\*2\^391-1 is prime! '
  assert_line --index 1 --regexp '^5\*2\^100-1 is not prime\. '
  [ "$(wc -l < whole.txt)" -eq 5 ]
  printf 'print(isprime(3*2^391-1), isprime(5*2^100-1), isprime(5), isprime(11), isprime(23))\n' | gp -q > gp.txt
  [ "$(cat gp.txt)" = "10111" ]
}

# crafted_checkpoints DIR CASES: for each line of the file CASES "NUMBER ITERATION RESIDUE
# [MEMBER]", a checkpoint with a valid checksum where riesel keeps NUMBER's
# (its --start llr), naming MEMBER (default NUMBER); RESIDUE is hex, or N or
# N+5 for the number itself.
crafted_checkpoints() {
  python3 - "$1" "$2" <<'PY'
import re, sys
def fnv1a(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) % 2**64
    return h
for line in open(sys.argv[2]):
    number, iteration, residue, *other = line.split()
    k, n, c = map(int, re.fullmatch(r"(\d+)\*2\^(\d+)([+-]1)", number).groups())
    N = k * 2**n + c
    residue = {"N": "%x" % N, "N+5": "%x" % (N + 5)}.get(residue, residue)
    member = (other[0] if other else number) + " start=llr"
    body = "riesel-checkpoint 1\n%s\n%s\n%s\n" % (member, iteration, residue)
    path = "%s/checkpoint-%016x" % (sys.argv[1], fnv1a((number + " start=llr").encode()))
    open(path, "w").write(body + "%016x\n" % fnv1a(body.encode()))
PY
}

@test "crafted checkpoints with valid checksums (iteration outside the proof, residue not below N, another number's) restart the proof with a warning" {
  # One prime each (A002235, A002253): 3*2^n-1 squares n-2 times, 3*2^n+1 n-1 times.
  cat > cases.txt <<'CASES'
3*2^94-1 99999999 5
3*2^76-1 -5 5
3*2^64-1 62 5
3*2^55-1 0 5
3*2^43-1 10 N
3*2^38-1 10 N+5
3*2^34-1 10 -5
3*2^103-1 10 5 3*2^105-1
3*2^66+1 99999999 5
3*2^41+1 10 N
CASES
  mkdir st
  crafted_checkpoints st cases.txt
  cut -d' ' -f1 cases.txt > in.txt
  sed -E 's/.*/print(isprime(&))/' in.txt | gp -q > gp.txt
  [ "$(sort -u gp.txt)" = 1 ]
  run --separate-stderr riesel --state st in.txt
  assert_success
  [ "$(json-field verdict <<< "$output" | sort | uniq -c | awk '{ print $1, $2 }')" = "10 prime" ]
  while read -r number; do
    [[ "$stderr" == *"checkpoint "*": proving $number from the start"* ]] || { echo "$number: stderr '$stderr'"; false; }
    grep -qF "$number is prime! " st/lresults.txt
  done < in.txt
  [[ "$stderr" == *"checkpoint iteration 99999999 is outside this proof (92 squarings)"* ]]
  [[ "$stderr" == *"checkpoint residue is not below N"* ]]
  [[ "$stderr" == *"checkpoint belongs to 3*2^105-1 start=llr"* ]]
}

# One bit flipped in a journal line: in the verdict ("prime" to "psime"),
# the key, a tab, each later field, the checksum, the newline. Every byte
# and bit is tried in-process by test_proof_journal.cpp; here the tool
# itself must refuse the line and prove the record again.
@test "a flipped bit in a journal line never replays a wrong verdict: the line is refused and the record proved again" {
  printf '%s\n' '3*2^391-1' '5*2^100-1' > in.txt
  printf 'print(if(isprime(3*2^391-1),"prime","composite"));print(if(isprime(5*2^100-1),"prime","composite"))\n' |
    gp -q > want.txt
  riesel --state base in.txt > /dev/null
  run python3 - <<'PY'
import json, shutil, subprocess
want = open("want.txt").read().split()
journal = open("base/journal.tsv", "rb").read()
line = journal[: journal.index(b"\n") + 1]
tabs = [i for i, byte in enumerate(line) if byte == 9]
positions = {
    line.index(b'"verdict":"prime"') + 12: 1,  # "prime" -> "psime"
    line.index(b"391"): 1,                     # the key's n
    tabs[0]: 2,
    tabs[0] + 20: 4,                           # inside the output record
    tabs[-1] - 3: 1,                           # the last field before the checksum
    len(line) - 3: 1,                          # the checksum (or the line's end)
    len(line) - 1: 4,                          # the newline
}
for position, bit in positions.items():
    damaged = bytearray(journal)
    damaged[position] ^= bit
    shutil.rmtree("st", ignore_errors=True)
    shutil.copytree("base", "st")
    open("st/journal.tsv", "wb").write(damaged)
    run = subprocess.run(["riesel", "--state", "st", "in.txt"], capture_output=True, text=True)
    verdicts = [json.loads(record)["verdict"] for record in run.stdout.splitlines()]
    assert run.returncode == 0 and verdicts == want, (position, run.returncode, run.stdout, run.stderr)
    assert "st/journal.tsv:1: journal line " in run.stderr, (position, run.stderr)
    assert open("st/journal.rejected", "rb").read().startswith(bytes(damaged[:10])), position
print("ok")
PY
  assert_output ok
}

@test "a journal from an older riesel (no checksums) is refused with a warning and its records proved again" {
  printf 'print(isprime(3*2^391-1))\n' | gp -q > gp.txt
  [ "$(cat gp.txt)" = 1 ]
  mkdir st
  printf 'start=llr {"k":3,"b":2,"n":391,"c":-1}\t{"k":3,"b":2,"n":391,"c":-1,"verdict":"composite","test":"llr","P":3,"res64":"0000000000000005","seconds":0.1}\n' > st/journal.tsv
  run --separate-stderr riesel --state st <<< '3*2^391-1'
  assert_success
  [ "$(json-field verdict <<< "$output")" = prime ]
  [[ "$stderr" == *"st/journal.tsv:1: journal line has no checksum (written by an older riesel)"* ]]
  grep -q '"verdict":"composite"' st/journal.rejected
  # Moved aside: the next run has nothing to warn about.
  run --separate-stderr riesel --state st <<< '3*2^391-1'
  assert_success
  [ -z "$stderr" ]
}
