#!/usr/bin/env bash
# JAria's client against AMRISim (MobileSim's successor), the reference simulator.
#
#   conformance/run-amrisim.sh AMRISIM_DIR PORT
#
# AMRISIM_DIR: built with ../shared/interop/build-amrisim.sh (needs libgtk2.0-dev, autotools and
# xvfb). Runs, each against a fresh AMRISim (office map, one p3dx): ./jaria demo wander, ./jaria
# demo goto, and conformance/LaserProbe.java (JAria's ArSimulatedLaser).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
amri="$1"; port="$2"
out="${OUT:-$here/out}"
mkdir -p "$out"

start_amrisim() {
  (cd "$amri" && AMRISIM="$amri" exec xvfb-run -a ./AMRISim --no-gui --noninteractive \
    -m AMROffice.map -r p3dx:robot1 -p "$port") >"$out/amrisim-$1.log" 2>&1 &
  amripid=$!
  for _ in $(seq 1 150); do
    grep -q "ready for a client" "$out/amrisim-$1.log" 2>/dev/null && break
    sleep 0.2
  done
}
stop_amrisim() {
  # AMRISim runs under xvfb-run and ignores SIGTERM: end it by its own id, then xvfb-run.
  local sim
  sim=$(pgrep -n -f "AMRISim --no-gui --noninteractive -m AMROffice.map -r p3dx:robot1 -p $port\$")
  [ -n "$sim" ] && kill -INT "$sim" 2>/dev/null && sleep 2 && kill -KILL "$sim" 2>/dev/null
  wait "$amripid" 2>/dev/null
  port=$((port + 1)) # AMRISim may leave the port in use for a while
}

for what in wander goto; do
  start_amrisim "$what"
  # the options after the subcommand: given before it, they would not reach it
  timeout 60 "$root/jaria" demo "$what" --remote "127.0.0.1:$port" --seconds 15 >"$out/jaria-$what.log" 2>&1
  echo "jaria demo $what: exit $? ($(tail -n 2 "$out/jaria-$what.log" | tr '\n' ' '))"
  stop_amrisim
done
start_amrisim laser
timeout 60 java -cp "$root/tools/target/jaria-tools.jar:$root/tools/target/lib/*" \
  "$here/LaserProbe.java" 127.0.0.1 "$port" >"$out/jaria-laser.log" 2>&1
echo "LaserProbe: exit $? ($(tr '\n' ' ' <"$out/jaria-laser.log"))"
stop_amrisim
