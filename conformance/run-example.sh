#!/usr/bin/env bash
# Runs ONE unmodified ARIA example against a fresh JAria simulator and prints one result line.
#
#   conformance/run-example.sh ARIA_DIR EXAMPLE PORT SECONDS [extra example args...]
#
# ARIA_DIR  a built ARIA tree (AriaCoda or ARIA 2.9.1) with lib/ and examples/
# EXAMPLE   the example's name (demo is driven through a pseudo-terminal, see keys below)
# PORT      the TCP port the simulator listens on (pick a free one)
# SECONDS   how long the example may run before it is stopped (examples that never end on
#           their own, like wander, are stopped after SECONDS: exit status 124)
#
# Environment: SIM (default: ./jaria sim, run from the repository root), SIM_ARGS (extra
# simulator options), OUT (directory for the logs, default conformance/out), ARGS_IN_ENV=1 (give
# the connection arguments in ARIAARGS instead of the command line, for examples that refuse
# unknown arguments themselves, like gyroExample), KEYS (keys to type into a keyboard-driven
# example through a pseudo-terminal, see below; demo has a default).
# The result line: example | connected | laser connected after | robot drove | protocol warnings |
# timing warnings | exit status | wall time. "Robot drove" is the length of the robot's true path
# (the simulator's odometer), not how far it ended from where it started.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
aria="$1"; example="$2"; port="$3"; seconds="$4"; shift 4
out="${OUT:-$here/out}"
sim="${SIM:-$root/jaria sim}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
aria="$(cd "$aria" && pwd)"
tag="$(basename "$aria")-$example"
simlog="$out/$tag.sim.log"
arialog="$out/$tag.aria.log"

# shellcheck disable=SC2086
$sim -p "$port" ${SIM_ARGS:-} >"$simlog" 2>&1 &
simpid=$!
for _ in $(seq 1 100); do
  grep -q "listening on TCP port" "$simlog" 2>/dev/null && break
  sleep 0.2
done

export ARIA="$aria" LD_LIBRARY_PATH="$aria/lib"
bin="$aria/examples/$example"
if [ "${ARGS_IN_ENV:-}" = 1 ]; then
  export ARIAARGS="-rh 127.0.0.1 -rrtp $port"
  args=("$@")
else
  args=(-rh 127.0.0.1 -rrtp "$port" "$@")
fi
# Examples write files into their working directory (lineFinderExample: points, lines): keep
# them with the logs.
cd "$out" || exit 1
# Every output line gets the wall time it arrived at (ARIA flushes each log line).
stamp() { while IFS= read -r line; do printf '%s %s\n' "$(date +%s.%N)" "$line"; done; }
start=$(date +%s.%N)
if [ "$example" = demo ] && [ -z "${KEYS:-}" ]; then
  # demo's modes: w wander, l laser, t teleop, then Escape quits.
  KEYS='4:w 6:l 3:t 2:\033'
fi
if [ -n "${KEYS:-}" ]; then
  # A keyboard-driven example reads single keys from its terminal: KEYS is a list of
  # "seconds-to-wait:key" (key in printf notation, e.g. \033[A for the up arrow, \033 Escape).
  keys() {
    for k in $KEYS; do sleep "${k%%:*}"; printf "${k#*:}"; done
    sleep 3
  }
  keys | timeout "$seconds" script -qefc "$bin ${args[*]}" /dev/null 2>&1 | tr -d '\r' | stamp >"$arialog"
  status=${PIPESTATUS[1]}
else
  timeout "$seconds" "$bin" "${args[@]}" </dev/null 2>&1 | stamp >"$arialog"
  status=${PIPESTATUS[0]}
fi

# TERM, not INT: a script's background job ignores SIGINT. The JVM stops cleanly on TERM.
kill -TERM "$simpid" 2>/dev/null
wait "$simpid" 2>/dev/null

connected=no
grep -q "Connected to robot" "$arialog" && connected=yes
laser="-"
t0=$(grep -a -m1 "Connected to robot" "$arialog" | cut -d' ' -f1)
t1=$(grep -a -m1 "Connected to simulated laser" "$arialog" | cut -d' ' -f1)
if [ -n "$t0" ] && [ -n "$t1" ]; then laser=$(printf '%.2f s' "$(echo "$t1 - $t0" | bc)"); fi
if grep -q "Failed to connect to simulated laser" "$arialog"; then laser=FAILED; fi
drove=$(sed -n 's/.*; drove \([0-9]*\) mm.*/\1 mm/p' "$simlog" | head -n1)
# Protocol trouble ARIA reports, and ARIA's "cycle took too long" timing warnings (which a
# loaded machine causes on its own) counted apart.
warnings=$(grep -aicE "No packet handler wanted|too many readings|could not|failed|incorrect number|no response|bad header|unrecognized" "$arialog")
timing=$(grep -aicE "took [0-9]+ ms to run|sync tasks too long" "$arialog")
elapsed=$(echo "$(date +%s.%N) - $start" | bc)
printf '%s | %s | %s | %s | %s | %s | %s | %.0f s\n' \
  "$example" "$connected" "$laser" "${drove:-?}" "$warnings" "$timing" "$status" "$elapsed"
