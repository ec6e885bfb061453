#!/usr/bin/env bash
# Installs kestrel into a scratch prefix, moves the prefix, then runs the moved install with no
# LD_LIBRARY_PATH: every in-tree plugin loads, and an installed graph (which includes other
# graph files) runs from an unrelated working directory.
# Usage: relocated_install.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
. "$(dirname "$0")/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/installed" > "$work/install.log"
mv "$work/installed" "$work/moved"
prefix=$work/moved

check_relative_rpaths "$prefix"
check_plugins "$prefix/bin/kestrel" "$build"
check_graph "$prefix/bin/kestrel" "$prefix/share/kestrel/graphs/paper_tracking.yaml" "$work/elsewhere"
echo "relocated install: ok"
