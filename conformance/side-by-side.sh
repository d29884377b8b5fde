#!/usr/bin/env bash
# The same unmodified ARIA programs against AMRISim (MobileSim's successor) and against
# `./jaria sim --profile mobilesim`, on the same map (AMRISim's AMROffice.map) with the same robot
# (a p3dx at the map's dock, turned to heading 0), and what a program could tell apart.
#
#   conformance/side-by-side.sh AMRISIM_DIR ARIA_DIR PORT
#
# AMRISIM_DIR: built with ../shared/interop/build-amrisim.sh (needs Xvfb); ARIA_DIR: a built
# AriaCoda (../shared/interop/build-ariacoda.sh) with wander, gotoActionExample, demo and
# dataLoggerExample. PORT: the first TCP port the simulators are asked for (each run takes the next; the relays
# take ports from PORT+1000 on).
#
# For each program and each simulator the script relays the program's connection through
# `socat -x`, which writes every byte both ways into OUT/<program>-<simulator>.hex; then
# conformance/SideBySide.java compares the two recordings (handshake, CONFIGpac field by field, SIP
# layout, sonar readings per SIP, motors at connect, digital I/O, laser scans and no-echo
# readings, how far and how much the robot turned, the commands the program sent) and prints a
# table; the programs' own output lines that matter are printed below it (demo's laser line,
# gotoActionExample's goals, dataLoggerExample's log columns). The last line says how many
# programs showed differences beyond noise.
#
# Environment: OUT (default conformance/out/side-by-side), JARIA (default ./jaria of this
# checkout), JARIA_CP (class path for SideBySide.java, default this checkout's tools/target jar and
# libraries), SECONDS_EACH (how long wander and dataLoggerExample run, default 20), START (the
# robot's start, default -2822,-2937,0: the dock, facing +x), PROGRAMS (which of the four to run,
# default all: "wander gotoActionExample demo dataLoggerExample").
#
# Why heading 0: AMRISim hands a start heading to its physics in radians although it is in
# degrees, so the dock's -91.9 degrees puts its robot at 134.5 degrees (-91.9 rad); with 0 both
# simulators start the robot the same way. MobileSim, which wrote the heading into a world file
# in degrees, did not do this.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
amri="$(cd "$1" && pwd)"; aria="$(cd "$2" && pwd)"; port="$3"
out="${OUT:-$here/out/side-by-side}"
jaria="${JARIA:-$root/jaria}"
cp="${JARIA_CP:-$root/tools/target/jaria-tools.jar:$root/tools/target/lib/*}"
secs="${SECONDS_EACH:-20}"
start="${START:--2822,-2937,0}"
export AMRISIM_ARGS="-m AMROffice.map -r p3dx:robot1 --start $start"
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# shellcheck source=conformance/amrisim-lib.sh
. "$here/amrisim-lib.sh"
jariapid=""
socatpid=""
# the relays listen on ports of their own, 1000 above the simulators'
relayport=$((port + 1000))
cleanup_all() {
  stop_pid "$socatpid"
  stop_pid "$jariapid"
  cleanup
}
trap cleanup_all EXIT

# Starts `./jaria sim --profile mobilesim` on AMRISim's map with a p3dx, asking for $port; sets
# jariapid and simport.
start_jaria() {
  # shellcheck disable=SC2086
  $jaria sim --profile mobilesim -m "$amri/AMROffice.map" -r p3dx:robot1 --start "$start" \
    -p "$port" \
    >"$out/jaria-$1.log" 2>&1 &
  jariapid=$!
  simport=""
  for _ in $(seq 1 300); do
    grep -q "listening on TCP port" "$out/jaria-$1.log" 2>/dev/null && simport=$port && break
    kill -0 "$jariapid" 2>/dev/null || break
    sleep 0.2
  done
  port=$((port + 1))
  [ -n "$simport" ]
}

# Runs program $1 (with keys $2, if any, through a pseudo-terminal) for at most $3 seconds through a
# socat relay to $simport, recording into $out/$1-$4.hex; the program's output goes to $1-$4.out.
run_through_relay() {
  local name="$1" keys="$2" limit="$3" tag="$4" relay="$relayport"
  relayport=$((relayport + 1))
  socat -x "TCP-LISTEN:$relay,bind=127.0.0.1,reuseaddr" "TCP:127.0.0.1:$simport" \
    2>"$out/$name-$tag.hex" &
  socatpid=$!
  sleep 0.5
  local dir="$out/$name-$tag.d"
  rm -rf "$dir"
  mkdir -p "$dir"
  if [ "$name" = dataLoggerExample ]; then
    # log every value ARIA's ArDataLogger offers, every second
    {
      echo "Section Data logging"
      echo "DataLog true"
      echo "DataLogInterval 1"
      echo "DataLogFormat TSV"
      for v in BatteryVoltage ChargeState Pose EncoderPose Encoders LeftVel RightVel TransVel \
        RotVel LeftStalled RightStalled StallBits Flags FaultFlags; do
        echo "DataLog$v true"
      done
    } >"$dir/dataLoggerExample.cfg"
  fi
  (
    cd "$dir" || exit 1
    export ARIA="$aria" LD_LIBRARY_PATH="$aria/lib"
    local bin="$aria/examples/$name"
    if [ -n "$keys" ]; then
      { for k in $keys; do sleep "${k%%:*}"; printf "${k#*:}"; done; sleep 3; } |
        timeout "$limit" script -qefc "$bin -rh 127.0.0.1 -rrtp $relay" /dev/null 2>&1 |
        tr -d '\r' >"$out/$name-$tag.out"
    else
      timeout "$limit" "$bin" -rh 127.0.0.1 -rrtp "$relay" </dev/null >"$out/$name-$tag.out" 2>&1
    fi
  )
  stop_pid "$socatpid"
  socatpid=""
}

# The output lines of program $1 (recorded as $2) worth comparing.
summary() {
  local f="$out/$1-$2.out"
  case "$1" in
    demo) grep -ao "Close: *[0-9]*mm *[-0-9.]* deg *Far: *[0-9]*mm *[-0-9.]* deg *[0-9]* readings" \
      "$f" | tail -n 1 ;;
    gotoActionExample) echo "goals set: $(grep -ac "Going to next goal" "$f")" ;;
    dataLoggerExample)
      local log="$out/$1-$2.d/dataLoggerExample.log"
      echo "columns: $(grep -a -m1 -i "time" "$log" | tr '\t' ',' | cut -c1-150)"
      echo "last row: $(tail -n 1 "$log" | tr '\t' ',' | cut -c1-150)" ;;
    *) echo "exit lines: $(tail -n 1 "$f" | cut -c1-100)" ;;
  esac
}

start_xvfb
differing=0
for name in ${PROGRAMS:-wander gotoActionExample demo dataLoggerExample}; do
  keys=""
  limit="$secs"
  case "$name" in
    gotoActionExample) limit=45 ;;
    # demo: laser mode after 4 s, Escape 8 s later
    demo) keys='4:l 8:\033' limit=25 ;;
  esac
  if [ ! -x "$aria/examples/$name" ]; then
    echo "== $name: not built in $aria"
    continue
  fi
  if start_amrisim "$name"; then
    simport="$amriport"
    run_through_relay "$name" "$keys" "$limit" amrisim
    stop_amrisim "$name"
  fi
  if start_jaria "$name"; then
    run_through_relay "$name" "$keys" "$limit" jaria
    stop_pid "$jariapid"
    jariapid=""
  else
    echo "./jaria sim did not start (see $out/jaria-$name.log)" >&2
  fi
  echo "== $name"
  if java -cp "$cp" "$here/SideBySide.java" "$out/$name-amrisim.hex" "$out/$name-jaria.hex"; then
    :
  else
    differing=$((differing + 1))
  fi
  echo "AMRISim: $(summary "$name" amrisim)"
  echo "JAria:   $(summary "$name" jaria)"
done
echo "programs with differences beyond noise: $differing"
