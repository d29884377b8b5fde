#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image. The zip you upload holds this
# file, run_autograder, and a copy of JAria's folder as jaria/ (Gradescope unpacks it in
# /autograder/source). It installs a JDK and bubblewrap, and builds JAria's command line.
set -euo pipefail
apt-get update
apt-get install -y --no-install-recommends openjdk-17-jdk-headless bubblewrap util-linux
cd /autograder/source/jaria
./jaria version
