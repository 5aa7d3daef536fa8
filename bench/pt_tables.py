#!/usr/bin/env python3
"""pt_tables.py - the README's fovpt tables from bench/results/pt.csv (make bench-pt).

usage: python3 bench/pt_tables.py [bench/results/pt.csv]
       python3 bench/pt_tables.py --write [bench/README.md]
           (rewrites the marked sections default, eqtime, eqrays, throughput, raytypes, bvh,
           temporal of bench/README.md from the committed CSVs; see bench/readme_sections.py)
Prints markdown:
  1. default budgets: speed-up over uniform4 and fovea / near-periphery PSNR per method;
  2. equal time: fovea PSNR (f1) of each foveated method given uniform4's time, minus
     uniform4's f1 (dB), with the measured time / target time; and of SELECTIVE / JIN minus
     UNIFORM Whitted at the spp of the same time;
  3. equal ray budget: the same gains against UNIFORM at the method's camera-ray count;
  4. the closest-hit throughput rows (fovpt against Embree); per ray type (camera, bounce)
     and scene with tinybvh when built in; from pt_bvh.csv beside it: build time and bytes per
     triangle of each acceleration structure;
  5. from pt_temporal.csv beside it: PSNR and flicker per temporal option of SELECTIVE;
  6. path tracing in log-polar space (the lp_ rows: fovlp.h's positions, fovpt_shade_points):
     fovea (f1) / near-periphery (f4) PSNR gain over uniform4 at uniform4's time, beside the
     best of layers / layers_fovea / layers_diam / layers_diam_fovea / zones at equal time.
"""
import os
import csv
import math
import sys

import readme_sections

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")


def f(v):
    try:
        return float(v)
    except ValueError:
        return math.nan


def fmt_db(v):
    return "n/a" if math.isnan(v) else "%.1f" % v


def tables(path):
    """The five tables as {section name: lines}; the text between them is the CLI's only."""
    sec = {}
    cur = []

    def print(line=""):  # noqa: A001 - collects instead of printing
        cur.append(line)
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    idx = {}
    scenes, gazes = [], []
    for r in rows:
        idx[(r["scene"], r["gaze"], r["method"], r["budget"])] = r
        if r["mode"] not in ("closest_hit", "camera", "bounce"):  # not the throughput rows
            if r["scene"] not in scenes:
                scenes.append(r["scene"])
            if r["gaze"] not in gazes:
                gazes.append(r["gaze"])

    def get(sc, gz, m, b="default"):
        return idx.get((sc, gz, m, b))

    # 1. default budgets
    meths = ["layers", "layers_diam", "zones", "selective", "jin"]
    print("| scene | gaze | " + " | ".join(m + ": speed-up, f1/f4 dB" for m in meths) + " | uniform4 f1/f4 |")
    print("|---|---|" + "---|" * len(meths) + "---|")
    for sc in scenes:
        for gz in gazes:
            u = get(sc, gz, "uniform4")
            if not u:
                continue
            cells = []
            for m in meths:
                r = get(sc, gz, m)
                cells.append("%.1fx, %s/%s" % (f(r["speedup"]), fmt_db(f(r["psnr_f1"])), fmt_db(f(r["psnr_f4"]))) if r else "")
            print("| %s | %s | %s | %s/%s |" % (sc, gz, " | ".join(cells), fmt_db(f(u["psnr_f1"])), fmt_db(f(u["psnr_f4"]))))
    sec["default"] = cur
    cur = []

    # 2. equal time
    eq = ["layers", "layers_fovea", "layers_diam", "layers_diam_fovea", "zones"]
    print("| scene | gaze | uniform4 f1 dB | " + " | ".join(eq) + " | selective vs uniform | jin vs uniform |")
    print("|---|---|---:|" + "---:|" * len(eq) + "---:|---:|")
    gains = {m: [] for m in eq + ["selective", "jin"]}
    skipped = []
    for sc in scenes:
        for gz in gazes:
            u = get(sc, gz, "uniform4")
            if not u:
                continue
            cells = []
            row_gains = {}
            for m in eq:
                r = get(sc, gz, m, "eqtime_uniform4")
                if not r:
                    cells.append("")
                    continue
                g = f(r["psnr_f1"]) - f(u["psnr_f1"])
                row_gains[m] = g
                cells.append("%+.1f (%.2f)" % (g, f(r["time_ms"]) / f(r["budget_time_ms"])))
            for m in ["selective", "jin"]:
                r, q = get(sc, gz, m), get(sc, gz, "uniform_eqt", "eqtime_" + m)
                if not r or not q:
                    cells.append("")
                    continue
                g = f(r["psnr_f1"]) - f(q["psnr_f1"])
                row_gains[m] = g
                cells.append("%+.1f (%s spp, %.2f)" % (g, q["spp_fovea"], f(q["time_ms"]) / f(r["time_ms"])))
            print("| %s | %s | %s | %s |" % (sc, gz, fmt_db(f(u["psnr_f1"])), " | ".join(cells)))
            if f(u["psnr_f1"]) >= 90.0:  # the fovea sees only the background: every method is exact there
                skipped.append((sc, gz))
            else:
                for m, g in row_gains.items():
                    gains[m].append(g)
    print()
    summ = []
    for m, v in gains.items():
        v = [x for x in v if not math.isnan(x)]
        if v:
            summ.append("%s %+.1f..%+.1f (mean %+.1f)" % (m, min(v), max(v), sum(v) / len(v)))
    print("Fovea gain at equal time, min..max over scenes and gazes%s: " % (
        " (without %s: the fovea sees only the background)" % ", ".join(a + " " + b for a, b in skipped) if skipped else "") + "; ".join(summ))
    sec["eqtime"] = cur
    cur = []

    # 3. equal ray budget
    em = ["layers", "layers_diam", "zones", "selective", "jin"]
    print("| scene | gaze | " + " | ".join(em) + " |")
    print("|---|---|" + "---:|" * len(em))
    for sc in scenes:
        for gz in gazes:
            cells = []
            for m in em:
                r, q = get(sc, gz, m), get(sc, gz, "uniform_eq", "eqrays_" + m)
                cells.append("%+.1f" % (f(r["psnr_f1"]) - f(q["psnr_f1"])) if r and q else "")
            if any(cells):
                print("| %s | %s | %s |" % (sc, gz, " | ".join(cells)))
    sec["eqrays"] = cur
    cur = []

    # 4. throughput
    tp = [r for r in rows if r["mode"] == "closest_hit"]
    if tp:
        print("| closest hit (%s) | rays | Mrays/s | time ms | Embree time / time |" % tp[0]["scene"])
        print("|---|---:|---:|---:|---:|")
        for r in tp:
            print("| %s | %s | %.2f | %.1f | %.3f |" % (r["method"], r["rays"], f(r["rays_per_s"]) * 1e-6, f(r["time_ms"]),
                                                    f(r["speedup"])))
    sec["throughput"] = cur
    cur = []

    # 4b. throughput per ray type and scene (fovpt / Embree / tinybvh in one run)
    rt = [r for r in rows if r["mode"] in ("camera", "bounce")]
    if rt:
        print("| scene | method | camera Mrays/s | bounce Mrays/s | camera: Embree time / time | "
              "bounce: Embree time / time |")
        print("|---|---|---:|---:|---:|---:|")
        keys = []
        for r in rt:
            if (r["scene"], r["method"]) not in keys:
                keys.append((r["scene"], r["method"]))
        for sc, m in keys:
            c = [r for r in rt if r["scene"] == sc and r["method"] == m and r["mode"] == "camera"]
            b = [r for r in rt if r["scene"] == sc and r["method"] == m and r["mode"] == "bounce"]
            if c and b:
                print("| %s | %s | %.2f | %.2f | %.3f | %.3f |" % (sc, m, f(c[0]["rays_per_s"]) * 1e-6, f(b[0]["rays_per_s"]) * 1e-6,
                                                                f(c[0]["speedup"]), f(b[0]["speedup"])))
    sec["raytypes"] = cur
    cur = []

    # 4c. acceleration structures (pt_bvh.csv beside it)
    bpath = os.path.join(os.path.dirname(path), "pt_bvh.csv")
    if os.path.exists(bpath):
        with open(bpath, newline="") as fh:
            brows = list(csv.DictReader(fh))
        print("| scene | method | layout | triangles | build ms | bytes per triangle | traversal bytes per triangle |")
        print("|---|---|---|---:|---:|---:|---:|")
        for r in brows:
            print("| %s | %s | %s | %s | %.1f | %.0f | %.0f |" % (r["scene"], r["method"], r["layout"], r["triangles"],
                                                              f(r["build_ms"]), f(r["bytes_per_tri"]),
                                                              f(r.get("traversal_bytes_per_tri", "nan"))))
    sec["bvh"] = cur
    cur = []

    # 5. temporal options
    tpath = os.path.join(os.path.dirname(path), "pt_temporal.csv")
    if os.path.exists(tpath):
        with open(tpath, newline="") as fh:
            trows = list(csv.DictReader(fh))
        print("| scene | option | alpha | PSNR f1 / f2 / f3 / f4 dB (turning view, last frame) | "
              "flicker f1 / f2 / f3 / f4 (static view, sRGB std) | reused % |")
        print("|---|---|---|---|---|---:|")
        for r in trows:
            print("| %s | %s | %s | %s / %s / %s / %s | %.4f / %.4f / %.4f / %.4f | %s |" % (
                r["scene"], r["option"], r["alpha"], fmt_db(f(r["psnr_f1"])), fmt_db(f(r["psnr_f2"])), fmt_db(f(r["psnr_f3"])),
                fmt_db(f(r["psnr_f4"])), f(r["flicker_f1"]), f(r["flicker_f2"]), f(r["flicker_f3"]), f(r["flicker_f4"]), r["reused_pct"]))
    sec["temporal"] = cur
    cur = []

    # 6. path tracing in log-polar space (lp_ rows), equal time with uniform4
    lp = [m for m in ["lp_cfov", "lp_cfov_taa", "lp_cfov_fovea", "lp_acuity", "lp_acuity_taa", "lp_acuity_fovea"]
          if any(k[2] == m for k in idx)]
    if not lp:
        print("(no lp_ rows in this pt.csv: make bench-pt writes them; ./build/bench_pt --lp --out FILE runs only them)")
    else:
        fov = ["layers", "layers_fovea", "layers_diam", "layers_diam_fovea", "zones"]
        print("| scene | gaze | uniform4 f1/f4 dB | " + " | ".join(lp) + " | best layers/zones f1 (f4) |")
        print("|---|---|---|" + "---:|" * len(lp) + "---|")
        for sc in scenes:
            for gz in gazes:
                u = get(sc, gz, "uniform4")
                if not u:
                    continue
                cells = []
                for m in lp:
                    r = get(sc, gz, m, "eqtime_uniform4")
                    cells.append("%+.1f/%+.1f (%.2f)" % (f(r["psnr_f1"]) - f(u["psnr_f1"]), f(r["psnr_f4"]) - f(u["psnr_f4"]),
                                                       f(r["time_ms"]) / f(r["budget_time_ms"])) if r else "")
                best = None
                for m in fov:
                    r = get(sc, gz, m, "eqtime_uniform4")
                    if r and (best is None or f(r["psnr_f1"]) > f(best["psnr_f1"])):
                        best = r
                bcell = "%s %+.1f (%+.1f)" % (best["method"], f(best["psnr_f1"]) - f(u["psnr_f1"]),
                                              f(best["psnr_f4"]) - f(u["psnr_f4"])) if best else ""
                print("| %s | %s | %s/%s | %s | %s |" % (sc, gz, fmt_db(f(u["psnr_f1"])), fmt_db(f(u["psnr_f4"])), " | ".join(cells), bcell))
    sec["lp"] = cur
    return sec


CAPTIONS = {
    "eqtime": "Equal time: fovea PSNR gain (dB) over uniform4 at uniform4's time (time / target), and of "
              "selective / jin over UNIFORM Whitted at the spp of the method's time",
    "eqrays": "Equal ray budget: fovea PSNR gain (dB) of each method over UNIFORM at its camera-ray count",
    "lp": "Path tracing in log-polar space at equal time: fovea / near-periphery PSNR gain (dB) over uniform4 "
          "(time / target)",
}


def main(argv):
    dest = readme_sections.target(argv)
    if dest:
        readme_sections.write_sections(dest, "pt_tables.py", tables(os.path.join(RESULTS, "pt.csv")))
        return 0
    sec = tables(argv[1] if len(argv) > 1 else os.path.join(RESULTS, "pt.csv"))
    first = True
    for name in ("default", "eqtime", "eqrays", "throughput", "raytypes", "bvh", "temporal", "lp"):
        if name not in sec:
            continue
        if not first:
            print()
        first = False
        if name in CAPTIONS:
            print(CAPTIONS[name])
            print()
        print("\n".join(sec[name]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
