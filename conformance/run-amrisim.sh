#!/usr/bin/env bash
# JAria's client against AMRISim (MobileSim's successor), the reference simulator.
#
#   conformance/run-amrisim.sh AMRISIM_DIR PORT
#
# AMRISIM_DIR: built with ../shared/interop/build-amrisim.sh (needs libgtk2.0-dev, autotools and
# Xvfb). Runs, each against a fresh AMRISim (office map, one p3dx): ./jaria demo wander, ./jaria
# demo goto, and conformance/LaserProbe.java (JAria's ArSimulatedLaser). PORT is where the first
# AMRISim is asked to listen; each next one is asked for the port after the last one's.
#
# Environment: OUT (folder for the logs, default conformance/out), JARIA (the jaria command line,
# default ./jaria of this checkout), JARIA_CP (class path for LaserProbe, default this checkout's
# tools/target jar and libraries).
#
# Why it works this way: after a client leaves, AMRISim closes its robot's listening port and opens
# it again; while the old connection is in TIME_WAIT it cannot, and after three tries two seconds
# apart it moves the robot to the next free port. So the script starts a fresh AMRISim for each
# client, reads the port AMRISim says it is ready on from its log (not the one it asked for), and
# stops each AMRISim by the process id it started (never by name: other simulators may run).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
amri="$(cd "$1" && pwd)"; port="$2"
out="${OUT:-$here/out}"
jaria="${JARIA:-$root/jaria}"
cp="${JARIA_CP:-$root/tools/target/jaria-tools.jar:$root/tools/target/lib/*}"
mkdir -p "$out"

amripid=""
xvfbpid=""

# AMRISim needs an X display even with --no-gui: one Xvfb for the whole run, on a display number it
# picks itself (-displayfd), ended by its process id.
start_xvfb() {
  local fdfile="$out/xvfb.display"
  : >"$fdfile"
  Xvfb -displayfd 3 -nolisten tcp -screen 0 640x480x24 3>"$fdfile" >"$out/xvfb.log" 2>&1 &
  xvfbpid=$!
  for _ in $(seq 1 50); do
    [ -s "$fdfile" ] && break
    sleep 0.1
  done
  display=":$(tr -d '\n' <"$fdfile")"
  if [ "$display" = ":" ]; then
    echo "Xvfb did not start (see $out/xvfb.log)" >&2
    exit 1
  fi
}

# Ends process $1: SIGINT (AMRISim's Ctrl-C), then SIGTERM, then SIGKILL, a few seconds apart.
stop_pid() {
  local pid="$1" sig
  [ -n "$pid" ] || return 0
  for sig in INT TERM KILL; do
    kill -"$sig" "$pid" 2>/dev/null || break
    for _ in $(seq 1 25); do
      kill -0 "$pid" 2>/dev/null || break 2
      sleep 0.2
    done
  done
  wait "$pid" 2>/dev/null
}

cleanup() {
  stop_pid "$amripid"
  stop_pid "$xvfbpid"
}
trap cleanup EXIT

# The TCP port AMRISim last said its robot is ready on (empty if it has not said so yet).
amrisim_port() {
  sed -n 's/.*ready for a client to connect.* on TCP port \([0-9][0-9]*\)\..*/\1/p' \
    "$out/amrisim-$1.log" 2>/dev/null | tail -n 1
}

# Starts AMRISim (log amrisim-$1.log) asking for $port; sets amripid and amriport.
start_amrisim() {
  # exec: the id of the background job is AMRISim's own
  (cd "$amri" && DISPLAY="$display" AMRISIM="$amri" exec ./AMRISim --no-gui --noninteractive \
    -m AMROffice.map -r p3dx:robot1 -p "$port") >"$out/amrisim-$1.log" 2>&1 &
  amripid=$!
  amriport=""
  # up to 30 s: it retries a busy port for 6 s before it moves on
  for _ in $(seq 1 150); do
    amriport=$(amrisim_port "$1")
    [ -n "$amriport" ] && break
    kill -0 "$amripid" 2>/dev/null || break
    sleep 0.2
  done
  if [ -z "$amriport" ]; then
    echo "AMRISim did not become ready (see $out/amrisim-$1.log)" >&2
    stop_pid "$amripid"
    amripid=""
    port=$((port + 1))
    return 1
  fi
  [ "$amriport" != "$port" ] && echo "note: AMRISim asked for port $port, listens on $amriport"
  return 0
}

stop_amrisim() {
  stop_pid "$amripid"
  amripid=""
  # The next AMRISim asks for the port after the last one this one reported (it moves its robot
  # after each session): the ports it used may still be in TIME_WAIT.
  local last
  last=$(amrisim_port "$1")
  port=$((${last:-$amriport} + 1))
}

start_xvfb
for what in wander goto; do
  if start_amrisim "$what"; then
    # the options after the subcommand: given before it, they would not reach it
    # shellcheck disable=SC2086
    timeout 60 $jaria demo "$what" --remote "127.0.0.1:$amriport" --seconds 15 \
      >"$out/jaria-$what.log" 2>&1
    echo "jaria demo $what: exit $? ($(tail -n 2 "$out/jaria-$what.log" | tr '\n' ' '))"
    stop_amrisim "$what"
  fi
done
if start_amrisim laser; then
  timeout 60 java -cp "$cp" "$here/LaserProbe.java" 127.0.0.1 "$amriport" \
    >"$out/jaria-laser.log" 2>&1
  echo "LaserProbe: exit $? ($(tr '\n' ' ' <"$out/jaria-laser.log"))"
  stop_amrisim laser
fi
