#!/usr/bin/env python3
"""sdf_tables.py - the README's tables from bench/results/sdf.csv (make bench-sdf).

usage: python3 bench/sdf_tables.py [bench/results/sdf.csv]
Prints markdown: the mean over scenes of the evaluation and time ratios against classic (same
spp, gaze; for foveated methods per fovea and refresh) with the errors, then every row.
"""
import csv
import sys
from collections import defaultdict


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "bench/results/sdf.csv"
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
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
        key = (r["method"], int(r["spp"]), r["gaze"], float(r["fovea_deg"]), float(r["refresh"]))
        if key not in groups:
            order.append(key)
        groups[key].append(dict(ev=float(c["evals_per_px"]) / float(r["evals_per_px"]), tr=float(r["speedup_vs_classic"]),
                                psnr=float(r["psnr"]), flip=float(r["flip"]),
                                mis_cl=float(r.get("hit_mismatch_vs_classic_pct", "nan")),
                                flip_cl=float(r.get("flip_vs_classic", "nan"))))
    print("| method | spp | gaze | fovea deg | refresh | classic/method evaluations | range | time ratio | range | "
          "PSNR dB | FLIP | FLIP vs classic | hit mismatch vs classic % (max) |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for key in sorted(order, key=lambda k: (k[1], k[0], k[2], k[3], -k[4])):
        v = groups[key]

        def mean(f):
            return sum(x[f] for x in v) / len(v)
        ev = [x["ev"] for x in v]
        tr = [x["tr"] for x in v]
        m, spp, gaze, fov, ref = key
        fov_s = f"{fov:g}" if fov > 0 else "-"
        print(f"| {m} | {spp} | {gaze} | {fov_s} | {ref:g} | {mean('ev'):.2f} | {min(ev):.2f} - {max(ev):.2f} | "
              f"{mean('tr'):.2f} | {min(tr):.2f} - {max(tr):.2f} | {mean('psnr'):.2f} | {mean('flip'):.4f} | "
              f"{mean('flip_cl'):.4f} | {max(x['mis_cl'] for x in v):.3f} |")
    print()
    print("| scene | method | spp | fovea | refresh | gaze | evals/px | time ms | speed-up | PSNR dB | SSIM | FLIP | hit mismatch % | traced % |")
    print("|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        fov = float(r["fovea_deg"])
        print(f"| {r['scene']} | {r['method']} | {r['spp']} | {fov:g} | {float(r['refresh']):g} | {r['gaze']} | "
              f"{float(r['evals_per_px']):.1f} | {float(r['time_ms']):.0f} | {float(r['speedup_vs_classic']):.2f} | "
              f"{float(r['psnr']):.2f} | {float(r['ssim']):.4f} | {float(r['flip']):.4f} | "
              f"{float(r['hit_mismatch_pct']):.3f} | {float(r.get('traced_pct', 100)):.1f} |")


if __name__ == "__main__":
    main()
