#!/usr/bin/env python3
"""sdf_tables.py - the README's tables from bench/results/sdf.csv (make bench-sdf).

usage: python3 bench/sdf_tables.py [bench/results/sdf.csv]
Prints markdown: the mean over scenes of the evaluation and time ratios against classic (same
spp, gaze; for foveated methods per fovea and refresh), then every row of the CSV.
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
        groups[key].append((float(c["evals_per_px"]) / float(r["evals_per_px"]), float(r["speedup_vs_classic"]),
                            float(r["psnr"]), float(r["psnr_e0_5"]) if r.get("psnr_e0_5") not in (None, "", "nan") else float("nan")))
    print("| method | spp | gaze | fovea deg | refresh | classic/method evaluations | range | time ratio | range | PSNR dB | PSNR inner 5 deg |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for key in sorted(order, key=lambda k: (k[1], k[0], k[2], k[3], -k[4])):
        v = groups[key]
        ev = [a for a, _, _, _ in v]
        tr = [b for _, b, _, _ in v]
        ps = [c for _, _, c, _ in v]
        p5 = [d for _, _, _, d in v]
        m, spp, gaze, fov, ref = key
        fov_s = f"{fov:g}" if fov > 0 else "-"
        print(f"| {m} | {spp} | {gaze} | {fov_s} | {ref:g} | {sum(ev) / len(ev):.2f} | {min(ev):.2f} - {max(ev):.2f} | "
              f"{sum(tr) / len(tr):.2f} | {min(tr):.2f} - {max(tr):.2f} | {sum(ps) / len(ps):.2f} | {sum(p5) / len(p5):.2f} |")
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
