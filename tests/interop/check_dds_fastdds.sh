#!/usr/bin/env bash
# kestrel on DDS against the other DDS that ROS 2 ships: an eProsima Fast DDS participant (ROS 2's
# default RMW, rmw_fastrtps) discovers the topics kestrel publishes through Cyclone DDS and must
# receive at least one message of each, images and clouds among them, by ROS 2's names and types.
# Usage: check_dds_fastdds.sh PEER_TOOL FASTDDS_PEER WORK_DIR
set -euo pipefail
peer=$1 fastdds=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
source "$here/dds/loopback.sh"
"$peer" publish "$DDS_DOMAIN" 30 interop "$work/sent.jsonl" &
publisher=$!
trap 'kill "$publisher" 2>/dev/null || true' EXIT
# Under the ASan suite the peer is built with the sanitizer, but Debian's libfastrtps is not, and
# Fast DDS 2.9 deletes its own statistics readers through a pointer of another size (ASan's
# new-delete-type-mismatch, inside libfastrtps, when the participant is deleted): not kestrel's code.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}new_delete_type_mismatch=0" \
  "$fastdds" "$DDS_DOMAIN" 20 rt/interop/frame/left rt/interop/frame/right rt/interop/frame/left/camera_info \
  rt/interop/frame/right/camera_info rt/interop/cloud rt/interop/state rt/interop/detections rt/interop/tracks \
  rt/interop/truth rt/tf | tee "$work/fastdds.jsonl"
tail -n 1 "$work/fastdds.jsonl" | grep -q '"ok": true'
