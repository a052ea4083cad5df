#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the probe with nothing but pkg-config and the compiler: build.sh <output program>
set -e
c++ -o "$1" "$(dirname "$0")/PkgConfigProbe.cpp" $(pkg-config --cflags --libs openrtm2)
