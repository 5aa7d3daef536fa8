#!/usr/bin/env python3
"""sdf_tables.py - the fovsdf tables of bench/README.md from the committed CSVs.

usage: python3 bench/sdf_tables.py [bench/results/sdf.csv]
           prints markdown: the mean over scenes of the evaluation and time ratios against
           classic (same spp, gaze; for foveated methods per fovea and refresh) with the
           errors, then every row
       python3 bench/sdf_tables.py --write [bench/README.md]
           rewrites the marked sections of bench/README.md (see bench/readme_sections.py):
             demo    bench/results/demo.csv (make demo writes out/demo.csv): the columns the
                     demo prints, one row per scene and method
             mean    bench/results/sdf.csv (make bench-sdf): the mean over scenes
             fov     bench/results/sdf_fov.csv (bench_sdf --fov-grid): the mean over scenes,
                     fovea 2.5 / 7.5 / 15 degrees, gaze at the centre (all rows in the CSV)
             frames  bench/results/sdf.csv: frame times per scene (1 spp, all cores) of the
                     methods a user picks between, with the issue-12 columns
             all     bench/results/sdf.csv: every row
             stress  bench/results/stress.csv (make bench-stress): per method and spp, the
                     sums over the six stress scenes
"""
import os
import sys
from collections import defaultdict

import readme_sections

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")


def read(path):
    """The rows of the default build (bench-sdf-native and bench-sdf-nosimd append rows of other
    builds, marked in the build column; CSVs from before that column are all default)."""
    return [r for r in readme_sections.read_csv(path) if r.get("build") in (None, "", "default")]


def mean_table(rows, foveas=None, gazes=None):
    classic = {}
    for r in rows:
        if r["method"] == "classic":
            classic[(r["scene"], r["spp"], r["gaze"])] = r
    groups = defaultdict(list)
    order = []
    for r in rows:
        c = classic.get((r["scene"], r["spp"], r["gaze"]))
        if r["method"] == "classic" or c is None:
            continue
        if foveas is not None and float(r["fovea_deg"]) not in foveas:
            continue
        if gazes is not None and r["gaze"] not in gazes:
            continue
        key = (r["method"], int(r["spp"]), r["gaze"], float(r["fovea_deg"]), float(r["refresh"]))
        if key not in groups:
            order.append(key)
        groups[key].append(dict(ev=float(c["evals_per_px"]) / float(r["evals_per_px"]), tr=float(r["speedup_vs_classic"]),
                                psnr=float(r["psnr"]), flip=float(r["flip"]),
                                mis_cl=float(r.get("hit_mismatch_vs_classic_pct", "nan")),
                                flip_cl=float(r.get("flip_vs_classic", "nan"))))
    out = ["| method | spp | gaze | fovea deg | refresh | classic/method evaluations | range | time ratio | range | "
           "PSNR dB | FLIP | FLIP vs classic | hit mismatch vs classic % (max) |",
           "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for key in sorted(order, key=lambda k: (k[1], k[0], k[2], k[3], -k[4])):
        v = groups[key]

        def mean(f):
            return sum(x[f] for x in v) / len(v)
        ev = [x["ev"] for x in v]
        tr = [x["tr"] for x in v]
        m, spp, gaze, fov, ref = key
        fov_s = f"{fov:g}" if fov > 0 else "-"
        out.append(f"| {m} | {spp} | {gaze} | {fov_s} | {ref:g} | {mean('ev'):.2f} | {min(ev):.2f} - {max(ev):.2f} | "
                   f"{mean('tr'):.2f} | {min(tr):.2f} - {max(tr):.2f} | {mean('psnr'):.2f} | {mean('flip'):.4f} | "
                   f"{mean('flip_cl'):.4f} | {max(x['mis_cl'] for x in v):.3f} |")
    return out


def every_row(rows):
    out = ["| scene | method | spp | fovea | refresh | gaze | evals/px | time ms | speed-up | PSNR dB | SSIM | FLIP | "
           "hit mismatch % | traced % |",
           "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        fov = float(r["fovea_deg"])
        out.append(f"| {r['scene']} | {r['method']} | {r['spp']} | {fov:g} | {float(r['refresh']):g} | {r['gaze']} | "
                   f"{float(r['evals_per_px']):.1f} | {float(r['time_ms']):.0f} | {float(r['speedup_vs_classic']):.2f} | "
                   f"{float(r['psnr']):.2f} | {float(r['ssim']):.4f} | {float(r['flip']):.4f} | "
                   f"{float(r['hit_mismatch_pct']):.3f} | {float(r.get('traced_pct', 100)):.1f} |")
    return out


FRAME_METHODS = ("classic", "cone", "cone_fov", "cone_fov_shfov", "naive", "cone_cb", "cone_fov_cb")


def frame_table(rows):
    """Per scene and method (1 spp, gaze at the centre, the default build): the frame on all
    cores (frame_ms, threads), evaluations per pixel (all, shadow rays), ns per evaluation on
    one thread, primitives per evaluation, and the speed-ups against naive and classic."""
    out = ["| scene | method | frame ms | threads | evals/px | shadow evals/px | ns/eval (1 thread) | prims/eval | "
           "speed-up vs naive | speed-up vs classic | PSNR dB |",
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        if r["method"] not in FRAME_METHODS or r["spp"] != "1" or r["gaze"] != "center" or "frame_ms" not in r:
            continue
        tot = float(r.get("evals_total_per_px") or r["evals_per_px"])
        out.append(f"| {r['scene']} | {r['method']} | {float(r['frame_ms']):.1f} | {r['threads']} | {tot:.1f} | "
                   f"{float(r['shadow_evals_per_px']):.1f} | {float(r['ns_per_eval']):.1f} | {float(r['prims_per_eval']):.2f} | "
                   f"{float(r['speedup_vs_naive']):.2f} | {float(r['speedup_vs_classic']):.2f} | {float(r['psnr']):.2f} |")
    return out


def demo_table(rows):
    """The columns and number formats examples/sdf_scenes.c prints (its ground-truth rows are
    not in the CSV)."""
    out = ["| scene | method | evals/px | primary | normal | shadow | skip% | time ms | psnr | ssim | flip | hit mis% | "
           "\\|dt\\|/t |",
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        out.append("| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f | %.4f | %.3f | %.2e |" % (
            r["scene"], r["method"], float(r["evals_per_px"]), float(r["primary"]), float(r["normal"]), float(r["shadow"]),
            float(r["prims_skipped_pct"]), float(r["time_ms"]), float(r["psnr"]), float(r["ssim"]), float(r["flip"]),
            float(r["hit_mismatch_pct"]), float(r["mean_rel_dt"])))
    return out


def stress_table(rows):
    """Per method and spp over the stress scenes: sample rays behind the first surface, head
    starts past the first hit, false hits, missed surfaces (sums), mean evaluations per pixel."""
    keys, agg = [], {}
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
        k = (int(r["spp"]), r["method"])
        if k not in agg:
            keys.append(k)
            agg[k] = dict(behind=0, start=0, false=0, missed=0, ev=[], worst=0)
        a = agg[k]
        a["behind"] += int(r["behind_smp"])
        a["start"] += int(r["start_bad"])
        a["false"] += int(r["false_hit"])
        a["missed"] += int(r["missed"])
        a["worst"] = max(a["worst"], int(r["behind_smp"]))
        a["ev"].append(float(r["evals_px"]))
    out = ["| spp | method | sample rays behind the first surface | worst scene | head starts past the first hit | "
           "false hits | missed surfaces | evals/px (mean of %d scenes) |" % len(scenes),
           "|---:|---|---:|---:|---:|---:|---:|---:|"]
    for k in sorted(keys, key=lambda k: (k[0], keys.index(k))):
        a = agg[k]
        out.append("| %d | %s | %d | %d | %d | %d | %d | %.2f |" % (k[0], k[1], a["behind"], a["worst"], a["start"], a["false"],
                                                                a["missed"], sum(a["ev"]) / len(a["ev"])))
    return out


def main(argv):
    dest = readme_sections.target(argv)
    if dest:
        readme_sections.write_sections(dest, "sdf_tables.py", {
            "demo": demo_table(read(os.path.join(RESULTS, "demo.csv"))),
            "mean": mean_table(read(os.path.join(RESULTS, "sdf.csv"))),
            "fov": mean_table(read(os.path.join(RESULTS, "sdf_fov.csv")), foveas=(2.5, 7.5, 15.0), gazes=("center",)),
            "frames": frame_table(read(os.path.join(RESULTS, "sdf.csv"))),
            "all": every_row(read(os.path.join(RESULTS, "sdf.csv"))),
            "stress": stress_table(read(os.path.join(RESULTS, "stress.csv"))),
        })
        return 0
    rows = read(argv[1] if len(argv) > 1 else os.path.join(RESULTS, "sdf.csv"))
    print("\n".join(mean_table(rows)))
    print()
    print("\n".join(every_row(rows)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
