#!/usr/bin/env bash
# Interop (CTest label `interop`): kestrel's MCAP writer and reader against @mcap/core, the
# reference implementation, at the versions pinned in tests/interop/package-lock.json.
# - @mcap/core reads kestrel's files (none, zstd, lz4 chunks) with every CRC checked, indexed and
#   streamed, and finds the messages, metadata and attachments kestrel wrote;
# - kestrel reads @mcap/core's files (none, zstd, lz4 chunks) and finds what it wrote.
# Usage: check_mcap_core.sh MCAP_TOOL WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tool=$1
work=$2
"$here/npm-install" "$work/node"
rm -rf "$work/kestrel" "$work/reference"
mkdir -p "$work/kestrel" "$work/reference"
cp "$here"/*.mjs "$work/node/"

"$tool" write "$work/kestrel" > "$work/kestrel/written.json"
for f in none zstd lz4; do
  node "$work/node/mcap_core_read.mjs" "$work/kestrel/$f.mcap" > "$work/kestrel/$f.read.json"
done
node "$work/node/mcap_core_write.mjs" "$work/reference" > "$work/reference/written.json"
for f in none zstd lz4; do
  "$tool" dump "$work/reference/$f.mcap" > "$work/reference/$f.dump.json"
done

python3 - "$work" <<'PY'
import json, os, sys
work = sys.argv[1]
def load(*p): return json.load(open(os.path.join(work, *p)))
def by_time(messages): return sorted(messages, key=lambda m: int(m["log_time"]))  # stable: ties in file order
def strip(m, keys): return {k: m[k] for k in keys}
keys = ["channel_id", "sequence", "log_time", "data"]

written = load("kestrel", "written.json")
for name, f in written.items():
    read = load("kestrel", name + ".read.json")
    assert read["profile"] == "ros2", read["profile"]
    assert read["compression"] == ([""] if name == "none" else [name]), read["compression"]
    assert read["statistics"]["messages"] == len(f["messages"]) == 60
    assert [strip(m, keys) for m in read["streamed_messages"]] == [strip(m, keys) for m in f["messages"]], name
    assert [strip(m, keys) for m in read["indexed_messages"]] == [strip(m, keys) for m in by_time(f["messages"])], name
    assert read["metadata"] == [{"name": "run", "metadata": {"graph": "nodes: []", "seed": "7"}}], read["metadata"]
    assert read["attachments"] == [{"name": "notes.txt", "media_type": "text/plain", "data": b"hello".hex()}]
    assert {c["topic"] for c in read["channels"]} == {"/text", "/raw"}
    print(f"@mcap/core reads kestrel's {name} file: {len(f['messages'])} messages, CRCs checked")

reference = load("reference", "written.json")
for name, f in reference.items():
    dump = load("reference", name + ".dump.json")
    assert dump["indexed"], name
    assert [strip(m, keys) for m in dump["messages"]] == [strip(m, keys) for m in by_time(f["messages"])], name
    assert dump["metadata"] == [{"name": "run", "metadata": {"seed": "7"}}], dump["metadata"]
    assert dump["attachments"] == [{"name": "notes.txt", "media_type": "text/plain", "data": b"hello".hex()}]
    print(f"kestrel reads @mcap/core's {name} file: {len(f['messages'])} messages, CRCs checked")
PY
