#!/usr/bin/env python3
"""lp_tables.py - the fovlp tables of bench/README.md from the committed CSVs (make bench-lp).

usage: python3 bench/lp_tables.py [bench/results/lp.csv]
           prints markdown: C Fov at sigma 1.7 (the thesis's Table 5.4 setting) against full
           resolution per scene, then the moving camera and gaze (lp_moving.csv beside it)
       python3 bench/lp_tables.py --write [bench/README.md]
           rewrites the marked sections cfov and moving of bench/README.md (see
           bench/readme_sections.py)
Columns of cfov: shaded = samples_pct; sample ratio = 100 / samples_pct; evaluation ratio =
eval_ratio (fovsdf distance evaluations, full / foveated); primitive-evaluation ratio =
prims_px_full / prims_smp_fov x the sample ratio; wall-time speed-up = speedup; hits =
hits_pct_full / hits_pct_fov; fovea = psnr_fovea (TAA output against 16 spp),
psnr_fovea_ref (against 256 spp), psnr_gt_fovea_ref (the 16-spp ground truth against 256).
"""
import os
import sys

import readme_sections

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")


read = readme_sections.read_csv


def cfov_table(rows, sigma=1.7):
    out = ["| scene | shaded | sample ratio | evaluation ratio | primitive-evaluation ratio | wall-time speed-up | "
           "hits full / foveated | fovea vs 16 spp | vs 256 spp | 16 spp itself vs 256 |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["mode"] != "C Fov" or abs(float(r["sigma"]) - sigma) > 1e-6:
            continue
        sp = float(r["samples_pct"])
        ratio = 100.0 / sp
        out.append("| %s | %.1f %% | %.2f | %.2f | %.2f | %.2f | %.0f / %.0f %% | %.1f dB | %.1f dB | %.1f dB |" % (
            r["scene"], sp, ratio, float(r["eval_ratio"]), float(r["prims_px_full"]) / float(r["prims_smp_fov"]) * ratio,
            float(r["speedup"]), float(r["hits_pct_full"]), float(r["hits_pct_fov"]), float(r["psnr_fovea"]),
            float(r["psnr_fovea_ref"]), float(r["psnr_gt_fovea_ref"])))
    return out


def moving_table(rows):
    out = ["| scene | TAA | history clamp | PSNR | error flicker, periphery | worst ring RMSE / no TAA |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        out.append("| %s | %s | %s | %.1f dB | %.4f | %.2f |" % (
            r["scene"], "on" if r["taa"] == "1" else "off", r["clamp"], float(r["psnr_all"]), float(r["flicker_periph"]),
            float(r["worst_ring_ratio"])))
    return out


def main(argv):
    dest = readme_sections.target(argv)
    if dest:
        readme_sections.write_sections(dest, "lp_tables.py", {
            "cfov": cfov_table(read(os.path.join(RESULTS, "lp.csv"))),
            "moving": moving_table(read(os.path.join(RESULTS, "lp_moving.csv"))),
        })
        return 0
    path = argv[1] if len(argv) > 1 else os.path.join(RESULTS, "lp.csv")
    print("\n".join(cfov_table(read(path))))
    mpath = os.path.join(os.path.dirname(path), "lp_moving.csv")
    if os.path.exists(mpath):
        print()
        print("\n".join(moving_table(read(mpath))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
