#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the probe with nothing but pkg-config and the compiler: build.sh <output program>
# CXXFLAGS and LDFLAGS are honoured as a user's build would (the asan test preset sets LDFLAGS).
set -e
c++ $CXXFLAGS -o "$1" "$(dirname "$0")/PkgConfigProbe.cpp" $(pkg-config --cflags --libs openrtm2) $LDFLAGS
