#!/usr/bin/env bash
# Renders the README's pictures of the desktop apps with `./jaria screenshot` (no display needed).
# Run from anywhere: ./docs/images/screenshots.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$root/docs/images"
cd "$root"
./jaria screenshot mapper aria-core/src/test/resources/reference/maps/columbia.map \
  -o "$out/mapper-columbia.png"
./jaria screenshot eztrain --train 30,67,70,75 --view thresh --blob-stats \
  -o "$out/eztrain-thresh.png"
./jaria screenshot eztrain --sim-camera --train 60,48,72,60 --view thresh --magnification 4 \
  --blob-stats -o "$out/eztrain-simcamera.png"
./jaria screenshot simview --map office --demo --advance 30000 --paused \
  --odometry-error constant:0.04,0.08 --region 0,5000,18000,14000 -o "$out/simview-office.png"
# The monitor needs a guiServer to watch: start one for a while, wait until it listens.
./jaria demo guiserver --map office --port 7399 --seconds 60 >/dev/null &
server=$!
for _ in $(seq 1 60); do
  (exec 3<>/dev/tcp/127.0.0.1/7399) 2>/dev/null && break
  sleep 1
done
./jaria screenshot monitor 127.0.0.1:7399 -o "$out/monitor-office.png"
kill "$server" 2>/dev/null || true
wait "$server" 2>/dev/null || true
