#!/usr/bin/env bash
# The Debian package installs as the README says (`apt-get install ./vectorfluid_*.deb`), starts,
# registers its file types, and `apt-get remove` takes it away again. That changes the system, so
# it runs only as root where CI is set (a throwaway machine); elsewhere it skips and says why.
#   deb-install.sh CPACK BUILD_DIR VERSION
set -euo pipefail
cpack=$1 build=$2 version=$3
[ -n "${CI:-}" ] || { echo "SKIP: installs into this system; runs only where CI is set"; exit 77; }
[ "$(id -u)" -eq 0 ] || { echo "SKIP: apt-get install needs root"; exit 77; }
command -v apt-get >/dev/null || { echo "SKIP: apt-get is not installed (a Debian system has it)"; exit 77; }
if dpkg-query -W -f='${Status}' vectorfluid 2>/dev/null | grep -q "install ok installed"; then
  echo "SKIP: vectorfluid is installed already; this test leaves that installation alone"; exit 77
fi
tmp=$(mktemp -d)
trap 'apt-get remove -y -qq vectorfluid >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT

"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp" >/dev/null
deb=$(ls "$tmp"/vectorfluid_*.deb)
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$deb" >/dev/null

[ "$(command -v vectorfluid)" = /usr/bin/vectorfluid ] || { echo "vectorfluid on PATH is $(command -v vectorfluid)"; exit 1; }
actual=$(vectorfluid --version)
[ "$actual" = "vectorfluid $version" ] || { echo "vectorfluid --version: $actual"; exit 1; }
# shared-mime-info's trigger ran on the package's file types.
[ -f /usr/share/mime/application/x-vectorfluid-project.xml ] || { echo "the MIME database lacks the project type"; exit 1; }

DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq vectorfluid >/dev/null
[ ! -e /usr/bin/vectorfluid ] || { echo "apt-get remove left /usr/bin/vectorfluid"; exit 1; }
[ ! -e /usr/share/mime/application/x-vectorfluid-project.xml ] || { echo "apt-get remove left the project type"; exit 1; }
echo "$(basename "$deb") installs, runs and goes"
