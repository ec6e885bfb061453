#!/usr/bin/env bash
# Builds the Debian package with CPack into a scratch folder, checks its runtime dependencies,
# unpacks it with `dpkg -x` into a scratch root (no root needed) and runs kestrel from there: every
# plugin loads and an installed graph runs.
# Usage: deb_package.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
. "$(dirname "$0")/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" > "$work/cpack.log" 2>&1 \
  || { cat "$work/cpack.log"; exit 1; }
deb=$(find "$work/package" -maxdepth 1 -name 'kestrel_*.deb')
[ -n "$deb" ] || { cat "$work/cpack.log"; echo "FAIL: no .deb"; exit 1; }
echo "package: $(basename "$deb"), $(du -h "$deb" | cut -f1)"

# Everything under /usr.
outside=$(dpkg-deb -c "$deb" | awk '{print $6}' | grep -v '^\./usr/' | grep -v '^\./$' || true)
[ -z "$outside" ] || { echo "FAIL: files outside /usr:"; echo "$outside"; exit 1; }

# Depends names the package of every library a packaged binary links, other than its own.
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
dpkg -x "$deb" "$work/root"
root=$work/root
declare -A dep_names=() libs=() owners=() needed=() paths_named=()
while IFS= read -r name; do dep_names[$name]=1; done < <(tr ',|' '\n\n' <<<"$depends" | awk 'NF {print $1}')
# The libraries the packaged binaries link directly, resolved on this machine (looked up in bash
# arrays, not by a process per line of ldd's output or per pair of paths: thousands fewer).
while IFS= read -r f; do
  head -c 4 "$f" | grep -q 'ELF' || continue
  needed=()
  while IFS= read -r soname; do [ -z "$soname" ] || needed[$soname]=1; done \
    < <(readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  while read -r soname path; do
    [ -n "$soname" ] && [ -n "${needed[$soname]:-}" ] || continue
    case "$path" in "$root"/*) ;; *) libs[$path]="${libs[$path]:-} ${f##*/}" ;; esac
  done < <(ldd "$f" | sed -n 's/^\s*\(\S*\) => \(\S*\) .*/\1 \2/p')
done < <(find "$root" -type f \( -path '*/bin/*' -o -name '*.so*' \))
# Their packages (one dpkg query; /lib and /usr/lib are the same folder on Debian 12).
patterns=()
for path in "${!libs[@]}"; do
  dir=${path%/*}
  patterns+=("*${dir##*/}/${path##*/}")
  paths_named[${path##*/}]+=" ${path##*/}"  # one entry per linked path of that file name
done
while IFS= read -r line; do
  pkg=${line%%: *} file=${line#*: }
  if [ -n "${paths_named[${file##*/}]:-}" ]; then owners[${pkg%%:*}]+=${paths_named[${file##*/}]}; fi
done < <(dpkg -S "${patterns[@]}" 2>/dev/null | grep -v '^diversion')
status=0
for pkg in "${!owners[@]}"; do
  ok=${dep_names[$pkg]:-}
  for provided in $(dpkg-query -W -f='${Provides}' "$pkg" | tr ',' ' ' | tr -d '()' | awk '{for(i=1;i<=NF;i++) if($i !~ /^[<>=0-9]/) print $i}'); do
    [ -n "${dep_names[$provided]:-}" ] && ok=1
  done
  [ -n "$ok" ] || { echo "FAIL: package $pkg (for${owners[$pkg]}) is not in Depends"; status=1; }
done
[ "${#libs[@]}" -gt 0 ] && [ "${#owners[@]}" -gt 0 ] || { echo "FAIL: no linked library resolved"; exit 1; }
[ "$status" -eq 0 ] || exit 1
echo "Depends covers the ${#owners[@]} packages of the ${#libs[@]} libraries the package links"

check_relative_rpaths "$root/usr"
check_plugins "$root/usr/bin/kestrel" "$build"
check_graph "$root/usr/bin/kestrel" "$root/usr/share/kestrel/graphs/sim_intercept.yaml" "$work/elsewhere"  # the demo graph
echo "Debian package: ok"
