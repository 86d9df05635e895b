#!/usr/bin/env bash
# Gradescope runs this once, as root, when the autograder is built (the zip's files are in
# /autograder/source). It installs lightbench from the package in the zip and a virtual X
# server. The package is built on Debian 12 (scripts/package): choose Gradescope's Ubuntu 24.04
# base image (Qt 6.4, as Debian 12), or build the package on the image's own system.
set -euo pipefail
cd "$(dirname "$0")"
apt-get update -qq
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    xvfb xauth python3 ./lightbench_*.deb
