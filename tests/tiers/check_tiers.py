"""Checks kestrel's tiers: runtime < libs < plugins, sensors < tools.

Usage: check_tiers.py TIERS_JSON SOURCE_DIR

TIERS_JSON lists every target of the build with its folder and what it links (written at the end
of configuration by tests/tiers/CMakeLists.txt). A unit is a folder: runtime, libs/NAME,
plugins/NAME, sensors/NAME, tools/NAME; its tests/ belong to it. The rules:
  - no target outside a plugin's or a sensor's folder links one of its targets: plugins are
    loaded, never linked (so deleting a plugin folder breaks only the graphs that use it);
  - otherwise a target links only targets of lower tiers or of its own unit (libraries may link
    libraries): the runtime links nothing of ours, a library no tool;
  - no source includes a file of another folder by a relative path ("../");
  - no header or source of a lower tier includes a header of a higher one (kestrel/NAME/ of a
    library from the runtime).
Prints every violation and exits 1 if there is one.
"""
import json
import pathlib
import re
import sys

RANK = {"runtime": 0, "libs": 1, "plugins": 2, "sensors": 2, "tools": 3}


def unit_of(folder):
    """('plugins', 'plugins/mavlink') for plugins/mavlink/tests; None outside the tiers."""
    parts = pathlib.PurePosixPath(folder).parts
    if not parts or parts[0] not in RANK:
        return None
    if parts[0] == "runtime":
        return ("runtime", "runtime")
    if len(parts) < 2:
        return (parts[0], parts[0])
    return (parts[0], f"{parts[0]}/{parts[1]}")


def main():
    targets = json.loads(pathlib.Path(sys.argv[1]).read_text())
    source = pathlib.Path(sys.argv[2])
    unit = {}
    for t in targets:
        u = unit_of(t["folder"])
        unit[t["target"]] = u
        if u and u[0] == "libs" and t["target"].startswith("kestrel_lib_"):
            unit["kestrel::" + t["target"][len("kestrel_lib_"):]] = u
    unit["kestrel::kestrel"] = unit.get("kestrel")
    unit["kestrel::messages"] = unit.get("kestrel_messages")

    errors = []
    checked = 0
    for t in targets:
        mine = unit[t["target"]]
        if mine is None:
            continue  # tests/, bench/, examples: they may use anything
        checked += 1
        for link in t["links"]:
            link = re.sub(r"^\$<LINK_ONLY:(.*)>$", r"\1", link)
            theirs = unit.get(link)
            if theirs is None or theirs[1] == mine[1]:
                continue  # a system library, or its own unit
            tier, other = theirs
            if tier in ("plugins", "sensors"):
                errors.append(f"{t['folder']}: {t['target']} links {link} of {other}: nothing outside a plugin's "
                              "folder links it (plugins are loaded, never linked)")
            elif RANK[tier] > RANK[mine[0]] or (tier == mine[0] and tier != "libs"):
                errors.append(f"{t['folder']}: {t['target']} links {link} of {other}, a tier above or beside it")

    libraries = {p.name for p in (source / "libs").iterdir() if (p / "include" / "kestrel" / p.name).is_dir()}
    include = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
    for path in sorted(source.glob("*/**/*")):
        if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
            continue
        rel = path.relative_to(source).as_posix()
        mine = unit_of(str(pathlib.PurePosixPath(rel).parent))
        if mine is None:
            continue
        for name in include.findall(path.read_text(errors="replace")):
            if name.startswith("../"):
                errors.append(f"{rel}: includes {name} by a relative path out of its folder")
            parts = name.split("/")
            if mine[0] == "runtime" and len(parts) > 2 and parts[0] == "kestrel" and parts[1] in libraries:
                errors.append(f"{rel}: the runtime includes {name}, a header of libs/{parts[1]}")

    for e in errors:
        print("tiers:", e)
    print(f"tiers: {checked} targets and their sources checked, {len(errors)} violation(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
