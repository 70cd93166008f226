#!/usr/bin/env bash
# CPack makes a Debian package that carries the installed files and depends on what the binary
# links (dpkg-shlibdeps) and loads at run time.
#   deb.sh CPACK BUILD_DIR
set -euo pipefail
cpack=$1 build=$2 id=org.vectorfluid.VectorFluid
for tool in dpkg-deb dpkg-shlibdeps; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed (a Debian system has it)"; exit 77; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp" >/dev/null
deb=$(ls "$tmp"/vectorfluid_*.deb)
dpkg-deb --info "$deb"

depends=$(dpkg-deb --field "$deb" Depends)
for needed in libqt6widgets6 libqt6gui6 libqt6core6 ocl-icd-libopencl1 libcairo2 libmuparser qt6-qpa-plugins fonts-dejavu-core; do
  [[ $depends == *"$needed"* ]] || { echo "Depends lacks $needed: $depends"; exit 1; }
done

files=$(dpkg-deb --contents "$deb" | awk '{print $6}' | grep -v '/$' | sort)
expected="./usr/bin/vectorfluid
./usr/share/applications/$id.desktop
./usr/share/icons/hicolor/scalable/apps/$id.svg
./usr/share/metainfo/$id.metainfo.xml
./usr/share/mime/packages/$id.xml"
[ "$files" = "$expected" ] || { printf 'packed:\n%s\nexpected:\n%s\n' "$files" "$expected"; exit 1; }
echo "package $(basename "$deb") fine"
