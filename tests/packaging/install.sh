#!/usr/bin/env bash
# `cmake --install` into a temporary DESTDIR lays out exactly the expected files, and the installed
# binary runs from a folder outside the source and build trees: the command line on both backends
# (kernels are embedded) and the app on a file given to it, as the launcher's `Exec=vectorfluid %f`.
#   install.sh CMAKE BUILD_DIR SCENE
set -euo pipefail
cmake=$1 build=$2 scene=$3 id=org.vectorfluid.VectorFluid
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

DESTDIR=$tmp/root "$cmake" --install "$build" --prefix /usr >/dev/null
expected="usr/bin/vectorfluid
usr/share/applications/$id.desktop
usr/share/icons/hicolor/scalable/apps/$id.svg
usr/share/metainfo/$id.metainfo.xml
usr/share/mime/packages/$id.xml"
actual=$(cd "$tmp/root" && find . -type f -o -type l | sed 's|^\./||' | sort)
[ "$actual" = "$expected" ] || { printf 'installed:\n%s\nexpected:\n%s\n' "$actual" "$expected"; exit 1; }
# As installed, the metainfo finds its launcher and icon.
if command -v appstreamcli >/dev/null; then
  appstreamcli validate-tree --no-net "$tmp/root"
else
  echo "SKIP installed tree validation: appstreamcli is not installed (scripts/setup installs it)"
fi

bin=$tmp/root/usr/bin/vectorfluid
mkdir "$tmp/work" "$tmp/home"
cp "$scene" "$tmp/work/scene.vfscene"
cd "$tmp/work"
"$bin" --version

for backend in reference opencl; do
  if [ $backend = opencl ] && "$bin" devices | grep -q '^no OpenCL devices'; then
    echo "SKIP opencl render: no OpenCL device"; continue
  fi
  "$bin" render scene.vfscene --steps 5 --backend $backend --out $backend.svg --stats $backend.json
  grep -q "\"backend\": *\"$backend\"" $backend.json || { echo "render ran on another backend than $backend"; exit 1; }
  xmllint --noout $backend.svg
done

# The app: started on the scene, it reports once its first frame is on screen and quits.
HOME=$tmp/home XDG_CONFIG_HOME= XDG_DATA_HOME= XDG_STATE_HOME= XDG_CACHE_HOME= \
  QT_QPA_PLATFORM=offscreen VF_EXIT_WHEN_READY=1 timeout 120 "$bin" scene.vfscene | grep 'interactive after'
echo "install layout and installed binary fine"
