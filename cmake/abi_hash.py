#!/usr/bin/env python3
"""Prints the ABI hash of kestrel's plugin-facing headers: a SHA-256 over their C++ token stream.

Comments and layout are not tokens, so a comment or whitespace edit leaves the hash unchanged,
while any change a compiler sees (a new field, a renamed type, another default) changes it.
Preprocessor directives keep their line ends, which are part of their meaning.

Usage: abi_hash.py ROOT [ROOT...]   (every *.hpp and *.h below each ROOT, by relative path,
                                     except the generated kestrel/version.hpp)
"""
import hashlib
import pathlib
import re
import sys

GENERATED = str(pathlib.PurePath("kestrel", "version.hpp"))

TOKEN = re.compile(
    r"""
      (?P<comment>//[^\n]*|/\*.*?\*/)
    | (?P<raw>R"(?P<delim>[^(\s]{0,16})\(.*?\)(?P=delim)")
    | (?P<string>"(?:\\.|[^"\\\n])*")
    | (?P<char>'(?:\\.|[^'\\\n])+')
    | (?P<word>[A-Za-z0-9_.]+)
    | (?P<newline>\n)
    | (?P<space>[ \t\r\f\v]+|\\\n)
    | (?P<punct>.)
    """,
    re.VERBOSE | re.DOTALL,
)


def tokens(text):
    """The file's tokens; a newline token only where it ends a preprocessor directive."""
    out = []
    in_directive = False
    at_line_start = True
    for m in TOKEN.finditer(text):
        kind = "raw" if m.group("raw") is not None else m.lastgroup
        if kind in ("comment", "space"):
            if kind == "comment" and "\n" in m.group(0) and in_directive:
                out.append("\\n")
                in_directive = False
                at_line_start = True
            continue
        if kind == "newline":
            if in_directive:
                out.append("\\n")
                in_directive = False
            at_line_start = True
            continue
        tok = m.group(0)
        if at_line_start and tok == "#":
            in_directive = True
        at_line_start = False
        out.append(tok)
    return out


def main(roots):
    digest = hashlib.sha256()
    files = []
    for root in roots:
        base = pathlib.Path(root)
        files += [(str(p.relative_to(base)), p) for p in base.rglob("*") if p.suffix in (".hpp", ".h") and p.is_file()]
    # kestrel/version.hpp is generated from this hash: in an installed tree it sits among the
    # headers, and it is not part of what it describes.
    files = [(rel, p) for rel, p in files if rel != GENERATED]
    for rel, path in sorted(files):
        digest.update(rel.encode() + b"\0")
        digest.update("\0".join(tokens(path.read_text(encoding="utf-8"))).encode() + b"\0")
    print(digest.hexdigest()[:12])


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
