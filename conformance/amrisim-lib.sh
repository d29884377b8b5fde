# Shell functions shared by the scripts that run AMRISim (MobileSim's successor) by hand:
# sourced, not run. The caller sets $out (folder for logs), $amri (AMRISim's folder) and $port
# (the port the next AMRISim is asked for), and calls start_xvfb once.
#
# Why it works this way: after a client leaves, AMRISim closes its robot's listening port and opens
# it again; while the old connection is in TIME_WAIT it cannot, and after three tries two seconds
# apart it moves the robot to the next free port. So each client gets a fresh AMRISim, its port is
# read from its log (not the one it was asked for), and each AMRISim is stopped by the process id
# this script started (never by name: other simulators may run).
# AMRISIM_ARGS (default: the office map and one p3dx) says what the AMRISim simulates.

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

# The TCP port AMRISim last said its robot is ready on (empty if it has not said so yet).
amrisim_port() {
  sed -n 's/.*ready for a client to connect.* on TCP port \([0-9][0-9]*\)\..*/\1/p' \
    "$out/amrisim-$1.log" 2>/dev/null | tail -n 1
}

# Starts AMRISim (log amrisim-$1.log) asking for $port; sets amripid and amriport.
start_amrisim() {
  # exec: the id of the background job is AMRISim's own
  # shellcheck disable=SC2086
  (cd "$amri" && DISPLAY="$display" AMRISIM="$amri" exec ./AMRISim --no-gui --noninteractive \
    ${AMRISIM_ARGS:--m AMROffice.map -r p3dx:robot1} -p "$port") >"$out/amrisim-$1.log" 2>&1 &
  amripid=$!
  disown "$amripid" # stopped by its id below; spares the "Killed" line of this shell
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

