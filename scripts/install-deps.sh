#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages RT Studio needs to build, test and run.
# Installs only what is missing; safe to run again; never asks questions.
set -euo pipefail

# dpkg-dev … apt: component packages (dpkg-deb, dpkg-shlibdeps, objdump) and signed repositories
# (gpg, gpgv; apt-get reads them in the tests). clang: the libFuzzer harnesses; lld links the test
# presets' programs. libz3-dev: the deployment planner's solver. python3-dev, pybind11-dev: the Python
# component API. busybox: its httpd serves a component repository in the deployment tests.
# libssl-dev, openssl: TLS (omniORB's SSL transport; certificates made with the openssl command).
packages=(
    build-essential cmake ninja-build pkg-config git
    qt6-base-dev qt6-base-dev-tools qt6-svg-dev libqt6svg6 qt6-qpa-plugins libgl-dev
    qt6-tools-dev qt6-l10n-tools qt6-translations-l10n fonts-ipafont-gothic qt6-charts-dev libqt6opengl6-dev
    libomniorb4-dev omniidl omniorb omniorb-nameserver omniorb-idl
    libkainjow-mustache-dev libyaml-cpp-dev libgraphviz-dev libz3-dev
    xvfb xauth fonts-dejavu-core ccache iproute2 clang lld
    dpkg-dev binutils gpg gpgv gpg-agent gpgconf xz-utils gzip apt busybox
    python3-dev pybind11-dev
    libssl-dev openssl
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
    sudo=sudo
else
    sudo=
fi
echo "Installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
