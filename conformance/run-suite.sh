#!/usr/bin/env bash
# The conformance suite: every ARIA example that needs only a robot and its standard accessories,
# unmodified, against a fresh `./jaria sim` each. Prints a Markdown table (the one in
# docs/simulator.md) and keeps each run's logs in conformance/out/.
#
#   conformance/run-suite.sh ARIA_DIR [BASE_PORT]
#
# ARIA_DIR: a built AriaCoda (../shared/interop/build-ariacoda.sh) or ARIA 2.9.1
# (../shared/interop/build-aria291.sh) tree; examples it lacks are listed as "not built".
# BASE_PORT: first TCP port to use (default 8101); each example takes the next one.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
aria="$1"
port="${2:-8101}"

# example  seconds  extra arguments.  Two examples need more than arguments:
# - gyroExample refuses any argument its own parser has not used: it gets them in ARIAARGS;
# - singleThreadLoopExample has no argument parser and always connects to localhost:8101: it runs
#   with its simulator in a private network namespace (bubblewrap), where 8101 is free.
suite=(
  "simpleConnect 20"
  "simpleMotionCommands 40"
  "wander 20"
  "demo 30"
  "gotoActionExample 40"
  "actionExample 20"
  "actionGroupExample 20"
  "laserConnect 20"
  "lasers 20"
  "lineFinderExample 20"
  "gyroExample 20"
  "gripperExample 20"
  "cameraPTZExample 60 -ptzType vcc4"
  "robotSyncTaskExample 20"
  "singleThreadLoopExample 20"
)

echo "| example | connected | laser connected after | robot drove | protocol warnings | timing warnings | exit status | ran |"
echo "|---|---|---|---|---|---|---|---|"
for entry in "${suite[@]}"; do
  read -r name seconds extra <<<"$entry"
  if [ ! -x "$aria/examples/$name" ]; then
    echo "| $name | not built | | | | | | |"
    continue
  fi
  keys=""
  case "$name" in
    # Keyboard-driven examples get keys through a pseudo-terminal (demo has its own default).
    gyroExample) keys='4:\033[A 0.5:\033[A 3:\033[D 3:\040 2:\033' ;;
    gripperExample) keys='4:o 3:d 4:c 3:u 4:\033' ;;
    actionGroupExample) keys='4:w 8:t 2:\033' ;;
    lineFinderExample) keys='5:f 3:f 3:\033' ;;
  esac
  if [ "$name" = gyroExample ]; then
    line=$(KEYS="$keys" ARGS_IN_ENV=1 "$here/run-example.sh" "$aria" "$name" "$port" "$seconds")
  elif [ "$name" = singleThreadLoopExample ]; then
    line=$(bwrap --dev-bind / / --unshare-net --die-with-parent \
      "$here/run-example.sh" "$aria" "$name" 8101 "$seconds")
  else
    # shellcheck disable=SC2086
    line=$(KEYS="$keys" "$here/run-example.sh" "$aria" "$name" "$port" "$seconds" $extra)
  fi
  echo "| $line |"
  port=$((port + 1))
done
