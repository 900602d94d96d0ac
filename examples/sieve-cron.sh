#!/usr/bin/env bash
# A cron-safe sieve: start it every quarter hour and it sieves on from its
# last checkpoint until the work is done, whatever happened in between
# (reboots, kills, a run still going).
#
# - flock: a run that finds the previous one still going exits at once.
# - --checkpoint + --resume: every run continues where the last one
#   stopped; a checkpoint is saved every 5 minutes and on SIGTERM (shutdown,
#   kill, the RUN_FOR time budget).
# - The output goes to a temporary file and is renamed when complete, so
#   twin.npg is either absent or whole.
#
# Crontab lines (crontab -e); cron's PATH is short, so name sieve's:
#   PATH=/usr/local/bin:/usr/bin:/bin
#   */15 * * * * SIEVE_DIR=$HOME/twin N=171960 KMAX=1e9 PMAX=1e12 bash $HOME/bin/sieve-cron.sh >> $HOME/twin/cron.log 2>&1
# or nights only, 22:00 to 06:00 (the SIGTERM at the end saves a checkpoint):
#   0 22 * * * SIEVE_DIR=$HOME/twin RUN_FOR=8h N=171960 KMAX=1e9 PMAX=1e12 bash $HOME/bin/sieve-cron.sh >> $HOME/twin/cron.log 2>&1
# Changing N, KMAX or PMAX later makes the old checkpoint an error (other
# parameters): use a new SIEVE_DIR.
#
# Run as is (no SIEVE_DIR) it shows itself in a scratch directory in a few
# seconds: a run stopped by its time budget, a run that finds the lock
# taken, the run that finishes, and one that finds the work done.
set -euo pipefail
n="${N:-1000}"
kmax="${KMAX:-1e6}"
pmax="${PMAX:-1e9}"

# One cron run.
sieve_step() {
  local dir="$SIEVE_DIR"
  local out="$dir/twin.npg" status=0
  mkdir -p "$dir"
  exec 9> "$dir/lock"
  if ! flock -n 9; then
    echo "$(date '+%F %T') another run holds $dir/lock: nothing to do"
    return 0
  fi
  if [[ -s "$out" ]]; then
    echo "$(date '+%F %T') done already: $out"
    return 0
  fi
  local budget=()
  if [[ -n "${RUN_FOR:-}" ]]; then budget=(timeout --signal=TERM "$RUN_FOR"); fi
  "${budget[@]}" sieve twin --n "$n" --k "1:$kmax" --pmax "$pmax" --newpgen -j "${THREADS:-2}" \
    --checkpoint "$dir/twin.ckpt" --resume --checkpoint-every 300 \
    > "$out.tmp" || status=$?
  case "$status" in
    0) mv "$out.tmp" "$out"
       echo "$(date '+%F %T') finished: $(( $(wc -l < "$out") - 1 )) candidates in $out" ;;
    124 | 130 | 143) echo "$(date '+%F %T') stopped (time budget, SIGINT or SIGTERM); the next run resumes" ;;
    *) echo "$(date '+%F %T') sieve failed with status $status" >&2
       return "$status" ;;
  esac
}

if [[ -n "${SIEVE_DIR:-}" ]]; then
  sieve_step
  exit
fi

# No SIEVE_DIR: the demonstration.
SIEVE_DIR="$(mktemp -d)"
trap 'rm -rf "$SIEVE_DIR"' EXIT
# Each run in a subshell, as cron would start it: the lock goes with it.
echo "== a run with a half-second budget (stops and saves, or finishes):"
( RUN_FOR=0.5s sieve_step )
echo "== a run while another holds the lock:"
flock "$SIEVE_DIR/lock" -c "SIEVE_DIR='$SIEVE_DIR' bash '$0'"
echo "== the next run, which goes on from the checkpoint:"
( sieve_step )
echo "== and one after the work is done:"
( sieve_step )
head -3 "$SIEVE_DIR/twin.npg"
sieve twin --n "$n" --k "1:$kmax" --pmax "$pmax" --newpgen -j 2 | cmp - "$SIEVE_DIR/twin.npg"
echo "== the same file as one uninterrupted run"
