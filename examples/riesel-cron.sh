#!/usr/bin/env bash
# Cron-safe proving: start it every quarter hour and it proves on from where
# the last run stopped, whatever happened in between (reboots, kills, a run
# still going). Then the same work split into shards for GNU parallel or a
# Slurm job array.
#
# riesel --state DIR (here $RIESEL_DIR/state) does the bookkeeping:
# - DIR/lock: a run that finds another one working on DIR stops at once
#   (exit 1, "another run holds this state directory's lock"); this script
#   treats that as "nothing to do".
# - DIR/journal.tsv: every finished record; a re-run writes them again
#   without proving them again.
# - DIR/checkpoint-*: the proofs in progress, saved every --checkpoint-every
#   seconds (300) and on SIGTERM (shutdown, kill, the RUN_FOR budget); a
#   re-run continues them where they stopped.
# - DIR/lresults.txt: every result in LLR's format, for people and scripts
#   that read LLR's.
# The output goes to a temporary file that is renamed when a run exits 0,
# so proved.jsonl is either absent or complete.
#
# Crontab lines (crontab -e); cron's PATH is short, so name riesel's:
#   PATH=/usr/local/bin:/usr/bin:/bin
#   */15 * * * * RIESEL_DIR=$HOME/twin INPUT=$HOME/twin/twin.npg bash $HOME/bin/riesel-cron.sh >> $HOME/twin/cron.log 2>&1
# or nights only, 22:00 to 06:00 (the SIGTERM at the end saves checkpoints):
#   0 22 * * * RIESEL_DIR=$HOME/twin INPUT=$HOME/twin/twin.npg RUN_FOR=8h bash $HOME/bin/riesel-cron.sh >> $HOME/twin/cron.log 2>&1
# INPUT is anything riesel reads: a NewPGen or ABC file from sieve, mrtest's
# JSON Lines, one number per line. Use a new RIESEL_DIR for new work.
#
# Shards (see the end of this script): --shard K/N proves every N-th record,
# the K-th of them; shards share nothing but the input, and each needs its
# own state directory. On this machine with GNU parallel:
#   parallel riesel --shard {}/4 --state state{} cand.npg '>' proved{}.jsonl ::: 1 2 3 4
# Over ssh on other machines (riesel on their PATH; input and state
# directories on a file system they all mount, so that a shard run again on
# another host finds its journal and checkpoints):
#   parallel -S 8/host1,8/host2 --wd /shared/twin riesel --shard {}/64 --state state{} cand.npg '>' proved{}.jsonl ::: $(seq 64)
# (8/host1 runs 8 shards at a time on host1.) As a Slurm job array, with
# checkpoints on preemption and time limits (Slurm sends SIGTERM first):
#   sbatch --array=1-64 --cpus-per-task=2 --requeue --chdir=/shared/twin --wrap 'riesel -j 2 --shard $SLURM_ARRAY_TASK_ID/64 --state state$SLURM_ARRAY_TASK_ID cand.npg > proved$SLURM_ARRAY_TASK_ID.tmp && mv proved$SLURM_ARRAY_TASK_ID.tmp proved$SLURM_ARRAY_TASK_ID.jsonl'
# Resubmitting the same array continues unfinished tasks; finished ones
# replay their journals in seconds. Together the shards' outputs hold every
# record of one run: cat proved*.jsonl.
#
# Run as is (no RIESEL_DIR) it shows itself in a scratch directory in 10 to
# 20 seconds: the candidates 3*2^n-1 for n = 12600..12700 (one is prime,
# n = 12676), a run stopped by its one-second budget, a run that finds the
# lock taken, the run that finishes, one that finds the work done, then
# the same candidates in four shards with GNU parallel.
set -euo pipefail
threads="${THREADS:-2}"

# The records without their members (the last field), so that a form's
# own verdict is the only one left on its line.
top_level() { sed 's/,"members":.*//' "$@"; }

# One cron run.
riesel_step() {
  local dir="$RIESEL_DIR" input="$INPUT"
  local out="$dir/proved.jsonl" status=0
  mkdir -p "$dir"
  if [[ -s "$out" ]]; then
    echo "$(date '+%F %T') done already: $out"
    return 0
  fi
  local budget=()
  if [[ -n "${RUN_FOR:-}" ]]; then budget=(timeout --signal=TERM "$RUN_FOR"); fi
  "${budget[@]}" riesel -j "$threads" -q --state "$dir/state" --checkpoint-every 300 "$input" \
    > "$out.tmp" 2> "$dir/riesel.err" || status=$?
  local finished=0
  if [[ -f "$dir/state/journal.tsv" ]]; then finished=$(wc -l < "$dir/state/journal.tsv"); fi
  case "$status" in
    0) mv "$out.tmp" "$out"
       echo "$(date '+%F %T') finished: $(wc -l < "$out") records in $out," \
         "$(top_level "$out" | grep -c '"verdict":"prime"' || true) proved prime" ;;
    124 | 130 | 143)
       echo "$(date '+%F %T') stopped (time budget, SIGINT or SIGTERM) with $finished records done" \
         "and $(find "$dir/state" -name 'checkpoint-*' | wc -l) proof(s) checkpointed; the next run resumes" ;;
    *) if grep -q "another run holds" "$dir/riesel.err"; then
         echo "$(date '+%F %T') another run holds $dir/state/lock: nothing to do"
         return 0
       fi
       cat "$dir/riesel.err" >&2
       echo "$(date '+%F %T') riesel failed with status $status" >&2
       return "$status" ;;
  esac
}

if [[ -n "${RIESEL_DIR:-}" ]]; then
  riesel_step
  exit
fi

# No RIESEL_DIR: the demonstration.
RIESEL_DIR="$(mktemp -d)"
trap 'rm -rf "$RIESEL_DIR"' EXIT
INPUT="$RIESEL_DIR/candidates.txt"
seq 12600 12700 | sed 's/^/3*2^/; s/$/-1/' > "$INPUT"
# Each run in a subshell, as cron would start it.
echo "== a run with a one-second budget (SIGTERM: it saves and stops):"
( RUN_FOR=1s riesel_step )
echo "== a run while another holds the lock:"
flock "$RIESEL_DIR/state/lock" -c "RIESEL_DIR='$RIESEL_DIR' INPUT='$INPUT' bash '$0'"
echo "== the next run, which replays the journal and resumes the checkpoint:"
( riesel_step )
echo "== and one after the work is done:"
( riesel_step )
top_level "$RIESEL_DIR/proved.jsonl" | grep '"verdict":"prime"'
echo "lresults.txt:"
head -3 "$RIESEL_DIR/state/lresults.txt"
echo "..."

echo "== the same candidates in 4 shards with GNU parallel, each with its own state:"
parallel --halt now,fail=1 riesel -q --shard "{}/4" --state "$RIESEL_DIR/shard{}" "$INPUT" \
  '>' "$RIESEL_DIR/proved{}.jsonl" ::: 1 2 3 4
wc -l "$RIESEL_DIR"/proved[1-4].jsonl | sed 's/^/  /'
# The shards hold the cron run's records (sorted by n here; seconds differ).
strip() { sed 's/,"seconds":[^,}]*//' "$@" | sort; }
cmp <(strip "$RIESEL_DIR"/proved[1-4].jsonl) <(strip "$RIESEL_DIR/proved.jsonl")
echo "the shards together hold the same records as the single run"
