#!/usr/bin/env python3
"""web_tables.py - the table of bench/results/web.csv (make bench-web: the browser demo in
headless chromium) beside bench/results/web_native.csv (make bench-web-native: the same
frames natively, one thread).

usage: python3 bench/web_tables.py [bench/results/web.csv [bench/results/web_native.csv]]
       python3 bench/web_tables.py --write [bench/README.md]
           (rewrites the marked section web of bench/README.md; see bench/readme_sections.py)
Prints markdown: per mode and size the frames per second of the foveated frame and of the
full-resolution reference (foveated / reference) for the scalar and SIMD128 modules with 1
and 2 workers, natively with one thread (gcc), the same modules in node with one thread, and
the speed-up (reference time over foveated time) of the SIMD build with 2 workers.
"""
import os
import sys

import readme_sections

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")


def table(web, native):
    rows = readme_sections.read_csv(web)
    nat = readme_sections.read_csv(native) if native and os.path.exists(native) else []
    key = lambda r: (r["mode"], r["width"], r["height"])
    order = []
    for r in rows:
        if key(r) not in order:
            order.append(key(r))
    def cell(rs, workers, simd):
        for r in rs:
            if r["workers"] == workers and r["simd"] == simd:
                return "%.1f / %.1f" % (float(r["fps_foveated"]), float(r["fps_reference"]))
        return "-"
    out = ["| mode | size | scalar, 1 worker | SIMD, 1 worker | scalar, 2 workers | SIMD, 2 workers "
           "| native, 1 thread | node SIMD, 1 thread | node scalar, 1 thread | speed-up (SIMD, 2 workers) |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for k in order:
        rs = [r for r in rows if key(r) == k]
        ns = [r for r in nat if key(r) == k]
        sp = "-"
        for r in rs:
            if r["workers"] == "2" and r["simd"] == "1":
                sp = "%.2fx" % float(r["ratio"])
        out.append("| %s (%s) | %sx%s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            k[0], rs[0]["scene"], k[1], k[2], cell(rs, "1", "0"), cell(rs, "1", "1"), cell(rs, "2", "0"),
            cell(rs, "2", "1"), cell(ns, "1", "native"), cell(ns, "1", "node-simd"),
            cell(ns, "1", "node-scalar"), sp))
    return out


def main(argv):
    dest = readme_sections.target(argv)
    web = argv[1] if len(argv) > 1 else os.path.join(RESULTS, "web.csv")
    native = argv[2] if len(argv) > 2 else os.path.join(RESULTS, "web_native.csv")
    lines = table(web, native)
    if dest:
        readme_sections.write_sections(dest, "web_tables.py", {"web": lines})
    else:
        print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv)
