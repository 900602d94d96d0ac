#!/usr/bin/env bash
#SBATCH --job-name=sieve-twin
#SBATCH --array=1-4
#SBATCH --cpus-per-task=2
#SBATCH --mem=2G
#SBATCH --time=24:00:00
#SBATCH --requeue
#SBATCH --output=sieve-%A_%a.log
#
# One sieve as a Slurm job array: task K of N runs --shard K/N, and a
# merge job that depends on the whole array joins the shards into what one
# run writes.
#
# On a cluster (SIEVE_DIR on a file system every node sees):
#   SIEVE_DIR=/shared/twin SHARDS=64 N=171960 KMAX=1e9 PMAX=1e12 \
#     bash sieve-slurm-array.sh submit
# which runs
#   sbatch --parsable --array=1-64 sieve-slurm-array.sh             -> JOBID
#   sbatch --dependency=afterok:JOBID --wrap "bash sieve-slurm-array.sh merge"
# The array must be 1-N: task K sieves shard K of N = SLURM_ARRAY_TASK_COUNT.
# Memory per task: the bitmap, one bit per k (125 MB for 10^9), plus a few
# MB per thread.
#
# Every task saves a checkpoint every 5 minutes and when Slurm sends
# SIGTERM (preemption, scancel, a node going down, the time limit), and
# starts with --resume, so a requeued or resubmitted task goes on where it
# stopped and a finished one exits at once. A task that hit its time limit
# is not requeued by Slurm: `scontrol requeue JOBID_K` (or submitting the
# same array again) continues it; the merge job waits until every task has
# succeeded.
#
# Outside Slurm (no SLURM_ARRAY_TASK_ID) the script simulates the array:
# a loop runs the tasks one after the other, the merge follows, and a
# single run checks the result. As is it takes a few seconds.
set -euo pipefail
n="${N:-1000}"
kmax="${KMAX:-1e6}"
pmax="${PMAX:-1e9}"
shards="${SHARDS:-4}"

# One array task: shard K of N.
run_task() {
  local k="$1" count="$2" out="$dir/shard$1.npg"
  if [[ -s "$out" ]]; then
    echo "shard $k/$count: already done"
    return 0
  fi
  # A killed sieve writes no output and exits by its signal, so the rename
  # happens only after a complete run.
  sieve twin --n "$n" --k "1:$kmax" --pmax "$pmax" --newpgen --shard "$k/$count" \
    -j "${SLURM_CPUS_PER_TASK:-1}" --checkpoint "$dir/shard$k.ckpt" --resume \
    --checkpoint-every 300 > "$out.tmp"
  mv "$out.tmp" "$out"
  echo "shard $k/$count: $(( $(wc -l < "$out") - 2 )) candidates left"  # header and shard line
}

# The merge job: every shard's output into one NewPGen file.
run_merge() {
  local files=() k
  for k in $(seq 1 "$shards"); do files+=("$dir/shard$k.npg"); done
  sieve merge "${files[@]}" > "$dir/twin.npg.tmp"
  mv "$dir/twin.npg.tmp" "$dir/twin.npg"
  echo "merged $shards shards: $(( $(wc -l < "$dir/twin.npg") - 1 )) candidates in $dir/twin.npg"
}

case "${1:-}" in
  submit)
    dir="${SIEVE_DIR:-$PWD/sieve-twin}"
    mkdir -p "$dir"
    export SIEVE_DIR="$dir" SHARDS="$shards" N="$n" KMAX="$kmax" PMAX="$pmax"
    script="$(readlink -f "$0")"
    jobid=$(sbatch --parsable --array="1-$shards" "$script")
    jobid="${jobid%%;*}"  # --parsable may add ";cluster"
    # --wrap: the merge is one job, not an array (the #SBATCH lines above
    # are read only from a script given as the job itself).
    sbatch --dependency="afterok:$jobid" --job-name=sieve-merge --output="sieve-merge-%j.log" \
      --wrap "bash '$script' merge"
    echo "array job $jobid with $shards tasks; the merge waits for it; result in $dir/twin.npg"
    ;;
  merge)
    dir="${SIEVE_DIR:-$PWD/sieve-twin}"
    run_merge
    ;;
  *)
    if [[ -n "${SLURM_ARRAY_TASK_ID:-}" ]]; then
      dir="${SIEVE_DIR:-$PWD/sieve-twin}"
      mkdir -p "$dir"
      run_task "$SLURM_ARRAY_TASK_ID" "${SLURM_ARRAY_TASK_COUNT:-$shards}"
    else
      # No Slurm: the array as a loop, in a scratch directory.
      dir="$(mktemp -d)"
      trap 'rm -rf "$dir"' EXIT
      for k in $(seq 1 "$shards"); do
        run_task "$k" "$shards"  # what task $k of the array runs
      done
      run_task 2 "$shards"  # a requeued task that had finished: nothing to do
      run_merge
      sieve twin --n "$n" --k "1:$kmax" --pmax "$pmax" --newpgen -j 2 | cmp - "$dir/twin.npg"
      echo "the merge equals one run byte for byte"
    fi
    ;;
esac
