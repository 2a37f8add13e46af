#!/bin/sh
# Runs `driftlab-cli run` into a store on an 8 MB tmpfs that fills up mid-run
# (in a private mount namespace: `unshare -rm sh run_on_a_full_disk.sh …`).
# MODE free: the filler is removed once the CLI warns, as an operator would;
# MODE keep: the disk stays full. Prints the run's exit code as `rc=N`;
# leaves the store (copied out of the tmpfs) and stderr in OUT.
set -u
CLI=$1 OUT=$2 PROCEDURE=$3 MODE=$4
DISK=$OUT/disk
mkdir -p "$DISK"
mount -t tmpfs -o size=8m tmpfs "$DISK" || exit 77
printf '%s' '{"format": "driftlab.procedure/1", "name": "first", "kind": "etve",
  "sample_interval_s": 1, "etve": {"run_id": "E0", "duration_s": 10}}' > "$OUT/first.json"
"$CLI" run --procedure "$OUT/first.json" --rig sim --db "$DISK/lab.sqlite" >/dev/null 2>&1 ||
    { echo "could not create the store"; exit 1; }
"$CLI" run --procedure "$PROCEDURE" --rig sim --db "$DISK/lab.sqlite" --speedup 500 \
    --max-unsaved-rows 1500 \
    > "$OUT/out" 2> "$OUT/err" &
run=$!
sleep 1
dd if=/dev/zero of="$DISK/filler" bs=4k 2>/dev/null
if [ "$MODE" = free ]; then
    i=0
    until grep -q '^warning: ' "$OUT/err" || [ $i -ge 300 ]; do sleep 0.1; i=$((i + 1)); done
    sleep 2
    rm "$DISK/filler"
fi
wait $run
echo "rc=$?"
cp "$DISK"/lab.sqlite* "$OUT/"
