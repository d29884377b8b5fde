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
# Each client gets a fresh AMRISim (amrisim-lib.sh says why).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
amri="$(cd "$1" && pwd)"; port="$2"
out="${OUT:-$here/out}"
jaria="${JARIA:-$root/jaria}"
cp="${JARIA_CP:-$root/tools/target/jaria-tools.jar:$root/tools/target/lib/*}"
mkdir -p "$out"

# shellcheck source=conformance/amrisim-lib.sh
. "$here/amrisim-lib.sh"
trap cleanup EXIT

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
