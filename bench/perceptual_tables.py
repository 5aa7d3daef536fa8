#!/usr/bin/env python3
"""perceptual_tables.py - the tables of bench/results/perceptual.csv (make bench-perceptual).

usage: python3 bench/perceptual_tables.py [bench/results/perceptual.csv]
       python3 bench/perceptual_tables.py --write [bench/README.md]
           (rewrites the marked sections perceptual and perceptual_sweep of bench/README.md;
           see bench/readme_sections.py)
Prints markdown:
  1. per header and display: the largest saving (above 1) at equal perceived quality (a
     configuration counts when its row has equal_quality 1 in every scene of that header; the
     equal-time rows *_eqt do not count; rows with still-view TAA, *_taa*, have a column of
     their own), and the fixed preset, the acuity configuration at the default quality (0.5)
     and at quality 1 beside it;
  2. the quality sweep of each acuity-driven family: per display and quality the saving (the
     least over the scenes), the mean perceptual error, and =, equal quality in every scene.
"""
import math
import os
import sys

import readme_sections

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")
FIXED = {"fovsdf": "cone_fov", "fovlp": "lp_c_fov", "fovpt": "layers"}
ACUITY = {"fovsdf": "cone_fov_acuity", "fovlp": "lp_acuity", "fovpt": "layers_acuity"}
DEFAULT_Q = 0.5  # fov_eye's default quality (tools/fov_shared.h)


def f(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def tables(path):
    rows = readme_sections.read_csv(path)
    headers, displays, scenes = [], [], {}
    for r in rows:
        if r["header"] not in headers:
            headers.append(r["header"])
        if r["display"] not in displays:
            displays.append(r["display"])
        scenes.setdefault(r["header"], [])
        if r["scene"] not in scenes[r["header"]]:
            scenes[r["header"]].append(r["scene"])
    by = {}
    for r in rows:
        by.setdefault((r["header"], r["display"], r["method"]), {})[r["scene"]] = r

    def summary(h, d, m):
        """(min saving over scenes, all equal, mean perr, mean perr_ref) or None."""
        got = by.get((h, d, m))
        if not got or len(got) != len(scenes[h]):
            return None
        sv = min(f(x["saving"]) for x in got.values())
        eq = all(x["equal_quality"] == "1" for x in got.values())
        pe = sum(f(x["perr"]) for x in got.values()) / len(got)
        pr = sum(f(x["perr_ref"]) for x in got.values()) / len(got)
        return sv, eq, pe, pr

    sec = {}
    out = ["| header | display | ppd at gaze | scenes | best at equal quality | saving | "
           "perr / ref | best with still-view TAA | %s | %s | %s |"
           % ("fixed preset: saving, perr, equal",
              "acuity default (quality %g): saving, perr, equal" % DEFAULT_Q,
              "acuity quality 1: saving, perr, equal"),
           "|---|---|---:|---|---|---:|---:|---|---|---|---|"]
    for h in headers:
        for d in displays:
            ms = [m for (hh, dd, m) in by if hh == h and dd == d]
            if not ms:
                continue
            pp = sorted({f(x["ppd_center"]) for x in by[(h, d, ms[0])].values()})
            ppd = "-".join("%.1f" % v for v in (pp if len(pp) < 3 else [pp[0], pp[-1]]))
            best, best_taa = None, None
            for m in ms:
                s = summary(h, d, m)
                if s is None or not s[1]:
                    continue
                ref = next(iter(by[(h, d, m)].values()))["ref_method"]
                if m == ref or m.endswith("_eqt") or not s[0] > 1.0:
                    continue
                if "_taa" in m:
                    if best_taa is None or s[0] > best_taa[1][0]:
                        best_taa = (m, s)
                elif best is None or s[0] > best[1][0]:
                    best = (m, s)
            taa = "-" if best_taa is None else "%s %.2fx" % (best_taa[0], best_taa[1][0])
            if best_taa is None and any("_taa" in m for m in ms):
                taa = "none"
            cells = []
            for m in (FIXED[h], "%s_q%g" % (ACUITY[h], DEFAULT_Q), ACUITY[h]):
                s = summary(h, d, m)
                cells.append("n/a" if s is None else "%.2fx, %.4f, %s" % (s[0], s[2], "yes" if s[1] else "no"))
            if best:
                bm = "%s" % best[0]
                bs = "%.2fx" % best[1][0]
                bp = "%.4f / %.4f" % (best[1][2], best[1][3])
            else:
                bm, bs, bp = "none", "1x", "-"
            out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |"
                       % (h, d, ppd, " ".join(scenes[h]), bm, bs, bp, taa, cells[0], cells[1],
                          cells[2]))
    sec["perceptual"] = out
    # 2. the quality sweep of each acuity family: saving (least over scenes) and mean perr
    fams = []
    for (h, d, m) in by:
        base = m.split("_q")[0]
        if "acuity" in base and (h, base) not in fams:
            fams.append((h, base))
    quals = sorted({f(x["quality"]) for r in by.values() for x in r.values()
                    if "acuity" in x["method"] and f(x["quality"]) > 0})
    out2 = ["| header | display | method | perr_ref | " + " | ".join("q %g" % q for q in quals) + " |",
            "|---|---|---|---:|" + "---:|" * len(quals)]
    for h, base in fams:
        for d in displays:
            cells, ref = [], None
            for q in quals:
                m = base if q == 1.0 else "%s_q%g" % (base, q)
                s = summary(h, d, m)
                if s is None:
                    cells.append("")
                    continue
                ref = s[3]
                cells.append("%.1fx %.4f%s" % (s[0], s[2], " **=**" if s[1] else ""))
            if ref is None:
                continue
            out2.append("| %s | %s | %s | %.4f | %s |" % (h, d, base, ref, " | ".join(cells)))
    sec["perceptual_sweep"] = out2
    return sec


def main(argv):
    dst = readme_sections.target(argv)
    path = argv[1] if len(argv) > 1 else os.path.join(RESULTS, "perceptual.csv")
    sec = tables(path)
    if dst:
        readme_sections.write_sections(dst, "perceptual_tables.py", sec)
    else:
        for name in ("perceptual", "perceptual_sweep"):
            print("\n".join(sec[name]))
            print()


if __name__ == "__main__":
    main(sys.argv)
