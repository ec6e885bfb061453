"""Checks that the docs name what the build has, so that they cannot drift from the code.

Usage: check_docs.py KESTREL_CLI SOURCE_DIR LIBRARY...

- README.md's plugin table (the table whose header starts "| plugin |") names every node type
  that `kestrel plugins` lists, as `type`, in the row of the folder that holds its plugin, and
  names no folder that is not there;
- README.md's graph table (header "| graph |") names every file of graphs/ as `graphs/NAME.yaml`,
  and none that is not there;
- docs/architecture.md's library table (header "| library |") names every installed library as
  `kestrel::NAME`, and no other.
Prints each difference and exits 1 if there is one.
"""
import pathlib
import re
import subprocess
import sys


def table(text, first_header):
    """The rows (lists of cells) of the first Markdown table whose first header cell is `first_header`."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and cells and cells[0] == first_header:
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append([c.strip() for c in row.strip().strip("|").split("|")])
            return rows
    return None


def quoted(cell):
    return re.findall(r"`([^`]+)`", cell)


def main():
    cli, source, libraries = sys.argv[1], pathlib.Path(sys.argv[2]), set(sys.argv[3:])
    errors = []
    readme = (source / "README.md").read_text()

    # Plugins: "name version (path/kestrel_name.so)" then "    node  TYPE  summary" lines.
    listing = subprocess.run([cli, "plugins"], capture_output=True, text=True, check=True).stdout
    node_types = {}  # type -> plugin
    plugin = None
    for line in listing.splitlines():
        if not line.startswith(" "):
            plugin = line.split()[0]
        elif line.split()[:1] == ["node"]:
            node_types[line.split()[1]] = plugin
    plugins = set(node_types.values()) | {l.split()[0] for l in listing.splitlines() if l and not l.startswith(" ")}
    rows = table(readme, "plugin")
    if rows is None:
        errors.append("README.md has no plugin table (| plugin | node types |)")
        rows = []
    by_folder = {}
    for row in rows:
        for folder in quoted(row[0]):
            by_folder[folder] = " ".join(row[1:])
            if not (source / folder).is_dir():
                errors.append(f"README.md's plugin table names {folder}, which is not there")
    folder_of = {}
    for folder in by_folder:
        name = pathlib.PurePosixPath(folder).name
        folder_of[name] = folder
    for plugin_name in sorted(plugins):
        if plugin_name not in folder_of and not any(
                (source / f / "CMakeLists.txt").is_file() and f"kestrel_add_plugin({plugin_name}" in
                (source / f / "CMakeLists.txt").read_text() for f in by_folder):
            errors.append(f"README.md's plugin table has no row for the plugin {plugin_name}")
    for node_type, plugin_name in sorted(node_types.items()):
        named = [f for f, text in by_folder.items() if f"`{node_type}`" in text]
        if not named:
            errors.append(f"README.md's plugin table does not name the node type {node_type} (plugin {plugin_name})")

    # Graphs.
    rows = table(readme, "graph")
    listed = set()
    if rows is None:
        errors.append("README.md has no graph table (| graph | what |)")
    else:
        for row in rows:
            listed.update(g for g in quoted(row[0]) if g.startswith("graphs/"))
    present = {f"graphs/{p.name}" for p in (source / "graphs").glob("*.yaml")}
    for g in sorted(present - listed):
        errors.append(f"README.md's graph table lacks {g}")
    for g in sorted(listed - present):
        errors.append(f"README.md's graph table names {g}, which is not there")

    # Libraries.
    architecture = (source / "docs" / "architecture.md").read_text()
    rows = table(architecture, "library")
    documented = set()
    if rows is None:
        errors.append("docs/architecture.md has no library table (| library | ... |)")
    else:
        for row in rows:
            documented.update(n[len("kestrel::"):] for n in quoted(row[0]) if n.startswith("kestrel::"))
    for name in sorted(libraries - documented):
        errors.append(f"docs/architecture.md's library table lacks kestrel::{name}")
    for name in sorted(documented - libraries):
        errors.append(f"docs/architecture.md's library table names kestrel::{name}, which is not installed")

    for e in errors:
        print("docs:", e)
    print(f"docs: {len(node_types)} node types, {len(present)} graphs, {len(libraries)} libraries checked; "
          f"{len(errors)} difference(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
