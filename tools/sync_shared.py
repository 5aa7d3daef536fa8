#!/usr/bin/env python3
"""Copy the shared regions of tools/fov_shared.h into fovsdf.h, fovlp.h and fovpt.h.

A region runs from a line starting "/* ==== FOV_SHARED_BEGIN <name>" to the next line starting
"/* ==== FOV_SHARED_END <name>", both included. Every header must hold the same regions, in the same
order, as the source file; each is replaced by the source's text, byte for byte.

    python3 tools/sync_shared.py           rewrite the headers' copies
    python3 tools/sync_shared.py --check   change nothing; exit 1 (and name the region) when a
                                           header's copy differs from the source
    --root DIR                             the repository (default: this script's parent)
"""
import os
import re
import sys

HEADERS = ("fovsdf.h", "fovlp.h", "fovpt.h")
BEGIN = re.compile(r"^/\* ==== FOV_SHARED_BEGIN (\w+)")
END = re.compile(r"^/\* ==== FOV_SHARED_END (\w+)")


def regions(lines, where):
    """[(name, first, last)] with first/last the indices of the BEGIN and END lines."""
    out, open_name, first = [], None, 0
    for i, line in enumerate(lines):
        b, e = BEGIN.search(line), END.search(line)
        if b:
            if open_name is not None:
                raise SystemExit("%s:%d: FOV_SHARED_BEGIN %s inside region %s"
                                 % (where, i + 1, b.group(1), open_name))
            open_name, first = b.group(1), i
        elif e:
            if e.group(1) != open_name:
                raise SystemExit("%s:%d: FOV_SHARED_END %s without its BEGIN"
                                 % (where, i + 1, e.group(1)))
            out.append((open_name, first, i))
            open_name = None
    if open_name is not None:
        raise SystemExit("%s: region %s is not closed" % (where, open_name))
    return out


def main(argv):
    check = "--check" in argv
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if "--root" in argv:
        root = argv[argv.index("--root") + 1]
    src_path = os.path.join(root, "tools", "fov_shared.h")
    with open(src_path, newline="") as f:
        src = f.read().split("\n")
    src_regions = regions(src, src_path)
    texts = {n: src[a:b + 1] for n, a, b in src_regions}
    names = [n for n, _, _ in src_regions]
    bad = 0
    for h in HEADERS:
        path = os.path.join(root, h)
        with open(path, newline="") as f:
            lines = f.read().split("\n")
        regs = regions(lines, path)
        if [n for n, _, _ in regs] != names:
            print("%s: regions %s, expected %s" % (h, [n for n, _, _ in regs], names))
            bad += 1
            continue
        out, pos, differ = [], 0, []
        for n, a, b in regs:
            out += lines[pos:a] + texts[n]
            if lines[a:b + 1] != texts[n]:
                differ.append(n)
            pos = b + 1
        out += lines[pos:]
        if differ:
            if check:
                print("%s: shared region(s) %s differ from tools/fov_shared.h"
                      % (h, ", ".join(differ)))
                bad += 1
            else:
                with open(path, "w", newline="") as f:
                    f.write("\n".join(out))
                print("%s: rewrote %s" % (h, ", ".join(differ)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
