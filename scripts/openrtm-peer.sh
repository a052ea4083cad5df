#!/bin/sh
# SPDX-License-Identifier: MIT
#
# Builds OpenRTM-aist 2.1 from a source tree and installs it into a prefix, to serve as a local
# test peer for the `interop` tests (it is never needed to build or use RT Studio):
#
#   scripts/openrtm-peer.sh SOURCE PREFIX [BUILD]
#   cmake -B build-ci -DRTSTUDIO_OPENRTM_PREFIX=PREFIX && ctest --test-dir build-ci -L interop
#
# SOURCE is an unpacked OpenRTM-aist v2.1.0 tree (its repository is public; from a bare clone:
# `git --git-dir=DIR archive v2.1.0 | tar -x -C SOURCE`). It is built with its SSL transport
# (SSL_ENABLE: lib/openrtm-2.1/ssl/SSLTransport.so), which tst_interoptls needs. Three mistakes of
# v2.1.0 keep a master from starting slave managers; they are corrected in SOURCE before the build:
#   - the manager command key lacks the dot in `manager.modules.<lang>.manager_cmd`;
#   - `-f ""` is passed to a slave when the master has an empty config_file;
#   - a child whose exec fails returns into the parent's code instead of exiting.
set -eu

if [ $# -lt 2 ]; then
    echo "usage: $0 SOURCE PREFIX [BUILD]" >&2
    exit 2
fi
src=$(cd "$1" && pwd)
prefix=$2
build=${3:-$src/build-peer}

servant=$src/src/lib/rtm/ManagerServant.cpp
process=$src/src/lib/coil/posix/coil/Process.cpp
for file in "$servant" "$process"; do
    if [ ! -f "$file" ]; then
        echo "$0: $file not found: is $src an OpenRTM-aist 2.1 source tree?" >&2
        exit 1
    fi
done

missing=
for package in libomniorb4-dev omniidl omniorb omniorb-nameserver omniorb-idl uuid-dev libssl-dev cmake ninja-build; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing="$missing $package"
done
if [ -n "$missing" ]; then
    if [ "$(id -u)" = 0 ]; then
        apt-get install -y --no-install-recommends $missing
    else
        echo "$0: install first (as root): apt-get install$missing" >&2
        exit 1
    fi
fi

# Each correction applies once; running the script again leaves the tree as it is.
sed -i 's/rtcd_cmd_key += lang + "manager_cmd";/rtcd_cmd_key += lang + ".manager_cmd";/' "$servant"
sed -i 's/else if (prop.findNode("config_file"))$/else if (prop.findNode("config_file") \&\& !prop["config_file"].empty())/' "$servant"
awk '/execvp\(vstr.front\(\).c_str\(\), argv.get\(\)\);/ { print; fixing = 1; next }
     fixing && NF { if ($0 ~ /^ *return -1;$/) sub(/return -1;/, "_exit(127);"); fixing = 0 }
     { print }' "$process" >"$process.peer" && mv "$process.peer" "$process"
grep -q 'lang + ".manager_cmd"' "$servant" && grep -q '_exit(127);' "$process" || {
    echo "$0: the source does not look like OpenRTM-aist v2.1.0; corrections not applied" >&2
    exit 1
}

cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DDOCUMENTS_ENABLE=OFF -DSSL_ENABLE=ON
ninja -C "$build"
ninja -C "$build" install

echo "OpenRTM-aist installed in $prefix"
echo "interop tests: cmake -B build-ci -DRTSTUDIO_OPENRTM_PREFIX=$prefix (or OPENRTM_ROOT=$prefix at the first configure)"
