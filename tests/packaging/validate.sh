#!/usr/bin/env bash
# The desktop files pass the freedesktop validators, declare the same file types, and name the
# project's version as the newest release.
#   validate.sh DESKTOP_DIR PROJECT_VERSION
set -euo pipefail
dir=$1 version=$2 id=org.vectorfluid.VectorFluid
for tool in desktop-file-validate appstreamcli xmllint update-mime-database; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed (scripts/setup installs it)"; exit 77; }
done

desktop-file-validate "$dir/$id.desktop"
appstreamcli validate --no-net "$dir/$id.metainfo.xml"
xmllint --noout "$dir/$id.xml" "$dir/$id.svg"

# The MIME database built from our types alone: each type has its glob, the project its magic.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/mime/packages"
cp "$dir/$id.xml" "$tmp/mime/packages/"
XDG_DATA_DIRS=$tmp update-mime-database "$tmp/mime"  # $tmp in the path: no note that it is not
grep -qx '50:application/x-vectorfluid-project:\*\.vfproj' "$tmp/mime/globs2"
grep -qx '50:application/x-vectorfluid-scene:\*\.vfscene' "$tmp/mime/globs2"
grep -qa 'VFPROJ ' "$tmp/mime/magic"

# The launcher, the metainfo and the MIME package list the same types.
types_xml=$(grep -o 'mime-type type="[^"]*"' "$dir/$id.xml" | cut -d'"' -f2 | sort)
types_desktop=$(sed -n 's/^MimeType=//p' "$dir/$id.desktop" | tr ';' '\n' | sed '/^$/d' | sort)
types_metainfo=$(sed -n 's:.*<mediatype>\(.*\)</mediatype>.*:\1:p' "$dir/$id.metainfo.xml" | sort)
[ "$types_xml" = "$types_desktop" ] || { echo "the .desktop MimeType differs from $id.xml"; exit 1; }
[ "$types_xml" = "$types_metainfo" ] || { echo "the metainfo's mediatypes differ from $id.xml"; exit 1; }

newest=$(grep -o '<release version="[^"]*"' "$dir/$id.metainfo.xml" | head -1 | cut -d'"' -f2)
[ "$newest" = "$version" ] || { echo "newest release in the metainfo is $newest, the project is $version"; exit 1; }
echo "desktop files valid"
