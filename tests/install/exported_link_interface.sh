#!/usr/bin/env bash
# The exported link interface: the runtime kestrel::kestrel, and every file of the kestrelTargets
# export set (installed and build-tree), name no OpenCV, PCL or MRPT; libkestrel.so needs none of
# them either. A plugin that finds kestrel must not be dragged into linking them.
# Usage: exported_link_interface.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
forbidden='opencv|pcl|mrpt'

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
mapfile -t files < <(find "$work/prefix" -path '*/cmake/kestrel/kestrelTargets*.cmake' | sort)
[ "${#files[@]}" -ge 2 ] || { echo "FAIL: no installed kestrelTargets*.cmake (found: ${files[*]:-none})"; exit 1; }

# kestrel::kestrel's INTERFACE_LINK_LIBRARIES, as the installed package declares it.
targets=$(dirname "${files[0]}")/kestrelTargets.cmake
link=$(sed -n '/^set_target_properties(kestrel::kestrel PROPERTIES/,/^)/s/^ *INTERFACE_LINK_LIBRARIES "\(.*\)"/\1/p' "$targets")
[ -n "$link" ] || { echo "FAIL: kestrel::kestrel has no INTERFACE_LINK_LIBRARIES in the installed package"; exit 1; }
echo "kestrel::kestrel INTERFACE_LINK_LIBRARIES: $link"
if grep -Eiq "$forbidden" <<<"$link"; then
  echo "FAIL: kestrel::kestrel's link interface names OpenCV, PCL or MRPT"
  exit 1
fi

# The whole export set, installed and in the build folder (paths of this machine taken out).
status=0
for f in "${files[@]}" "$build/kestrelTargets.cmake"; do
  if sed -e "s|$build||g" -e "s|$(dirname "$build")||g" "$f" | grep -Eino "$forbidden"; then
    echo "FAIL: $f names OpenCV, PCL or MRPT (lines above)"
    status=1
  else
    echo "clean: ${f#"$work/"}"
  fi
done

lib=$(find "$work/prefix" -name 'libkestrel.so.*' -type f | head -n 1)
needed=$(readelf -d "$lib" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
echo "libkestrel.so needs: $needed"
if grep -Eiq "$forbidden" <<<"$needed"; then
  echo "FAIL: libkestrel.so links OpenCV, PCL or MRPT"
  status=1
fi
exit $status
