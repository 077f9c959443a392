#!/usr/bin/env bash
# Copy the ITF1788 interval test vectors (Apache-2.0, see LICENSE/NOTICE/AUTHORS in the
# source directory) into tests/data/itf1788/, where tests/itf1788.rs parses them at test
# time. CI has no /work/shared, so the copy is checked in; rerun this script to refresh it.
#
# Usage: tools/import-itf1788.sh [SOURCE_DIR]   (default: /work/shared/testdata/itf1788)
set -euo pipefail
cd "$(dirname "$0")/.."
src="${1:-/work/shared/testdata/itf1788}"
dest="tests/data/itf1788"
if [ ! -d "$src" ]; then
    echo "import-itf1788: source directory $src not found" >&2
    exit 1
fi
mkdir -p "$dest"
rm -f "$dest"/*.itl
for f in "$src"/*.itl; do
    cp "$f" "$dest/"
done
for f in LICENSE NOTICE AUTHORS README; do
    if [ -f "$src/$f" ]; then
        cp "$src/$f" "$dest/"
    fi
done
chmod u+w "$dest"/*
echo "import-itf1788: copied $(ls "$dest"/*.itl | wc -l) .itl files from $src to $dest"
