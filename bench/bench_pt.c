/* bench_pt.c - fovpt benchmark: every method on the code-written scenes (bench/pt_scenes.h),
   gaze at the centre and near the top-left corner; writes bench/results/pt.csv.

   make bench-pt            default run (5 scenes, 320x240, ground truth 512 spp path / 64
                            Whitted; about 10-15 minutes on one busy core pair)
   make bench-pt FULL=1     640x480, ground truth 1024 spp, every equal-budget row
   ./build/bench_pt [--quick] [--full] [--throughput] [--w W --h H] [--gt-spp N] [--out FILE]
                    [--threads N]      (--throughput: only the fovpt / Embree ray-rate rows)

   Columns (the first eleven are the issue's, in order):
     scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,
     mode,rays,camera_rays,speedup
   - method: uniform1 / uniform4 (the non-foveated renderer at 1 and 4 spp, seed 002's
     regular system uses 4), layers (seed 002, 6/10/20 deg as radii), layers_diam (as
     diameters), zones (seed 000 ch. 4), selective (seed 004), jin (Jin et al. 2009);
     uniform_eq rows: UNIFORM at the spp that matches the ray count of the method named in
     `budget` (equal ray budget; equal time is the same here: one tracer, one core).
   - mode: path (path tracing, max depth 8, NEE) for uniform/layers/zones; whitted (depth 3)
     for selective/jin/whitted1 (seed 004 is a Whitted ray tracer); each against the ground
     truth of its own mode: UNIFORM at --gt-spp samples (path) or 64 (Whitted).
   - rays_per_s: all rays (camera, bounce, shadow) / time, ONE thread (per core);
     time_ms: wall time of the method on one thread (trace + refine + resolve).
   - psnr_f1..f4: PSNR (peak 1, sRGB-encoded clamped values) over the annuli of eccentricity
     [0, 3.3), [3.3, 5.5), [5.5, 12.1), [12.1, 30) degrees (seed 004's fovea, parafovea,
     perifovea, near periphery), psnr_all over the image; eccentricity from the camera's
     field of view (fovpt_ecc_*). An empty annulus gives nan.
   - speedup: time of uniform4 / time of the method (same scene and gaze).
   Embree rows (built with -DPT_HAVE_EMBREE -lembree3, which the Makefile adds when
   <embree3/rtcore.h> exists; Debian's libembree-dev): on the triangles of mesh100k alone,
   the same ray set (every pixel-centre camera ray, plus one cosine-distributed bounce ray
   from each camera hit, from a fixed-seed generator) is traced for the closest hit by
   fovpt_intersect and by Embree 3 (rtcIntersect1, a device with threads=1), one thread
   each, best of 5 runs interleaved (fovpt, Embree, fovpt, ...); rows fovpt_bvh and embree, budget rays_<N>, mode
   closest_hit, speedup = Embree's time / this row's time; the hit agreement (same hit or
   miss, |dt| <= 1e-4 t) is printed. */
#define _POSIX_C_SOURCE 200809L
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "pt_scenes.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef PT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

typedef struct job {
    fovpt_ctx *ctx;
    uint32_t y0, y1, frame;
    fovpt_stats st;
} job;
static void *worker(void *a)
{
    job *j = (job *)a;
    fovpt_trace_rows(j->ctx, j->frame, j->y0, j->y1, &j->st);
    return NULL;
}

/* renders with cfg; threads > 1 only for ground truths (UNIFORM: no refine phase) */
static double render(pt_scene *S, const fovpt_config *cfg, fov_gaze g, float *rgb, fovpt_stats *st, int threads)
{
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    double t0, t;
    memset(st, 0, sizeof *st);
    if (fovpt_memory_size(cfg, &S->cam, &n) != FOV_OK) return -1.0;
    mem = malloc(n + 16u);
    if (fovpt_init(&ctx, cfg, &S->scene, &S->cam, g, mem, n) != FOV_OK) { free(mem); return -1.0; }
    fovpt_output_init(&out);
    out.rgb = rgb;
    t0 = now_ms();
    if (threads <= 1) {
        fovpt_render(&ctx, 0, &out, st);
    } else {
        pthread_t th[16];
        job jobs[16];
        int i;
        uint32_t H = S->cam.height;
        for (i = 0; i < threads; ++i) {
            memset(&jobs[i], 0, sizeof jobs[i]);
            jobs[i].ctx = &ctx;
            jobs[i].y0 = H * (uint32_t)i / (uint32_t)threads;
            jobs[i].y1 = H * (uint32_t)(i + 1) / (uint32_t)threads;
            pthread_create(&th[i], NULL, worker, &jobs[i]);
        }
        for (i = 0; i < threads; ++i) {
            pthread_join(th[i], NULL);
            st->rays += jobs[i].st.rays;
            st->camera_rays += jobs[i].st.camera_rays;
        }
        fovpt_refine_rows(&ctx, 0, 0, H, st);
        fovpt_resolve_rows(&ctx, 0, H, &out);
    }
    t = now_ms() - t0;
    free(mem);
    return t;
}

static double srgb(double v)
{
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

/* PSNR over eccentricity annuli [lo, hi) */
static void psnr_fields(const float *a, const float *ref, const float *ecc, size_t np, double out[5])
{
    static const double lo[5] = { 0.0, 3.3, 5.5, 12.1, -1.0 }, hi[5] = { 3.3, 5.5, 12.1, 30.0, 1e9 };
    int f;
    for (f = 0; f < 5; ++f) {
        double se = 0.0;
        size_t i, cnt = 0;
        int k;
        for (i = 0; i < np; ++i) {
            if (ecc[i] < lo[f] || ecc[i] >= hi[f]) continue;
            for (k = 0; k < 3; ++k) {
                double d = srgb(a[3 * i + k]) - srgb(ref[3 * i + k]);
                se += d * d;
            }
            cnt += 3;
        }
        out[f] = cnt ? (se > 0.0 ? 10.0 * log10((double)cnt / se) : 99.0) : NAN;
    }
}

/* ---- ray throughput on triangles: fovpt's BVH against Embree (one thread each) ---------- */
static uint64_t g_rng = 0x243f6a8885a308d3ull;
static float rnd01(void)
{
    g_rng ^= g_rng << 13; g_rng ^= g_rng >> 7; g_rng ^= g_rng << 17;
    return (float)(g_rng >> 40) * (1.0f / 16777216.0f);
}
static void throughput_rows(FILE *csv, uint32_t W, uint32_t H)
{
    pt_scene S;
    fovpt_scene tri;
    fovpt_scene_desc d;
    size_t bytes = 0, nr = 0, cap, i, agree = 0;
    float *org, *dir, *t_pt;
    void *mem;
    uint32_t x, y, nprim;
    double best_pt = 1e30, best_em = -1.0;
    int rep;
    if (pt_scene_make(&S, PT_SCENE_MESH) != 0) return;
    S.cam.width = W; S.cam.height = H;
    d = S.desc;
    d.shapes = NULL; d.num_shapes = 0;          /* the triangles alone */
    d.background[0] = d.background[1] = d.background[2] = 0.0f;
    if (fovpt_scene_size(&d, &bytes) != FOV_OK) return;
    mem = malloc(bytes + 16u);
    if (fovpt_scene_build(&tri, &d, mem, bytes) != FOV_OK) return;
    nprim = tri.num_prims;
    cap = 2u * (size_t)W * H;
    org = (float *)malloc(cap * 12u); dir = (float *)malloc(cap * 12u); t_pt = (float *)malloc(cap * 4u);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            fovpt_camera_ray(&S.cam, (float)x + 0.5f, (float)y + 0.5f, org + 3 * nr, dir + 3 * nr);
            nr++;
        }
    for (i = 0, x = (uint32_t)nr; i < x; ++i) { /* one bounce ray per camera hit */
        fovpt_hit h;
        if (fovpt_intersect(&tri, org + 3 * i, dir + 3 * i, 0.0f, 1e30f, &h)) {
            float n[3], t1[3], b1[3], u1 = rnd01(), u2 = rnd01(), r = sqrtf(u1), ph = 6.2831853f * u2, lx, ly, lz;
            float sg = (h.n[0] * dir[3 * i] + h.n[1] * dir[3 * i + 1] + h.n[2] * dir[3 * i + 2]) > 0.0f ? -1.0f : 1.0f;
            int k;
            for (k = 0; k < 3; ++k) n[k] = sg * h.n[k];
            if (fabsf(n[0]) > 0.5f) { t1[0] = n[1]; t1[1] = -n[0]; t1[2] = 0.0f; } else { t1[0] = 0.0f; t1[1] = n[2]; t1[2] = -n[1]; }
            { float l = sqrtf(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]); t1[0] /= l; t1[1] /= l; t1[2] /= l; }
            b1[0] = n[1] * t1[2] - n[2] * t1[1]; b1[1] = n[2] * t1[0] - n[0] * t1[2]; b1[2] = n[0] * t1[1] - n[1] * t1[0];
            lx = r * cosf(ph); ly = r * sinf(ph); lz = sqrtf(1.0f - u1);
            for (k = 0; k < 3; ++k) {
                org[3 * nr + k] = h.p[k] + 1e-3f * n[k];
                dir[3 * nr + k] = lx * t1[k] + ly * b1[k] + lz * n[k];
            }
            nr++;
        }
    }
#ifndef PT_HAVE_EMBREE
    for (rep = 0; rep < 5; ++rep) {
        double t0 = now_ms(), t;
        for (i = 0; i < nr; ++i) {
            fovpt_hit h;
            t_pt[i] = fovpt_intersect(&tri, org + 3 * i, dir + 3 * i, 0.0f, 1e30f, &h) ? h.t : -1.0f;
        }
        t = now_ms() - t0;
        if (t < best_pt) best_pt = t;
    }
#else
    {
        RTCDevice dev = rtcNewDevice("threads=1");
        RTCScene sc = rtcNewScene(dev);
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, S.mesh.num_vertices);
        unsigned *ib = (unsigned *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, S.mesh.num_triangles);
        struct RTCIntersectContext ictx;
        memcpy(vb, S.mesh.positions, 12u * S.mesh.num_vertices);
        memcpy(ib, S.mesh.indices, 12u * S.mesh.num_triangles);
        rtcCommitGeometry(g);
        rtcAttachGeometry(sc, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(sc);
        rtcInitIntersectContext(&ictx);
        best_em = 1e30;
        for (rep = 0; rep < 5; ++rep) { /* interleaved, so load from other jobs hits both alike */
            double t0 = now_ms(), t;
            size_t ag = 0;
            for (i = 0; i < nr; ++i) {
                fovpt_hit h;
                t_pt[i] = fovpt_intersect(&tri, org + 3 * i, dir + 3 * i, 0.0f, 1e30f, &h) ? h.t : -1.0f;
            }
            t = now_ms() - t0;
            if (t < best_pt) best_pt = t;
            t0 = now_ms();
            for (i = 0; i < nr; ++i) {
                struct RTCRayHit rh;
                float te;
                rh.ray.org_x = org[3 * i]; rh.ray.org_y = org[3 * i + 1]; rh.ray.org_z = org[3 * i + 2];
                rh.ray.dir_x = dir[3 * i]; rh.ray.dir_y = dir[3 * i + 1]; rh.ray.dir_z = dir[3 * i + 2];
                rh.ray.tnear = 0.0f; rh.ray.tfar = 1e30f; rh.ray.time = 0.0f; rh.ray.mask = 0xFFFFFFFFu; rh.ray.id = 0; rh.ray.flags = 0;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(sc, &ictx, &rh);
                te = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : -1.0f;
                if ((te < 0.0f && t_pt[i] < 0.0f) || (te >= 0.0f && t_pt[i] >= 0.0f && fabsf(te - t_pt[i]) <= 1e-4f * te)) ag++;
            }
            t = now_ms() - t0;
            if (t < best_em) best_em = t;
            agree = ag;
        }
        rtcReleaseScene(sc);
        rtcReleaseDevice(dev);
    }
#endif
    printf("ray throughput on %u triangles, %zu rays (closest hit, one thread, best of 5 interleaved runs): fovpt %.2f Mrays/s", nprim, nr,
           (double)nr / (best_pt * 1e3));
    fprintf(csv, "mesh100k,fovpt_bvh,centre,rays_%zu,%.0f,%.2f,nan,nan,nan,nan,nan,closest_hit,%zu,%u,%.3f\n", nr, (double)nr / (best_pt * 1e-3),
            best_pt, nr, W * H, best_em > 0.0 ? best_em / best_pt : 0.0);
    if (best_em > 0.0) {
        printf(", Embree %.2f Mrays/s (fovpt/Embree %.2f), hits agree on %.3f %% of the rays\n", (double)nr / (best_em * 1e3),
               best_em / best_pt, 100.0 * (double)agree / (double)nr);
        fprintf(csv, "mesh100k,embree,centre,rays_%zu,%.0f,%.2f,nan,nan,nan,nan,nan,closest_hit,%zu,%u,1.000\n", nr, (double)nr / (best_em * 1e-3),
                best_em, nr, W * H);
    } else {
        printf(" (Embree: not built in; apt-get install libembree-dev)\n");
    }
    free(org); free(dir); free(t_pt); free(mem);
    pt_scene_free(&S);
}

int main(int argc, char **argv)
{
    uint32_t W = 320, H = 240, gt_spp = 512;
    int full = 0, quick = 0, only_tp = 0, threads = 2, i, sc, gi;
    const char *out_path = "bench/results/pt.csv";
    FILE *csv;
    double t_start = now_ms();
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--full")) full = 1;
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--throughput")) only_tp = 1;
        else if (!strcmp(argv[i], "--w") && i + 1 < argc) W = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) H = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--gt-spp") && i + 1 < argc) gt_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) out_path = argv[++i];
        else { fprintf(stderr, "usage: %s [--quick] [--full] [--throughput] [--w W --h H] [--gt-spp N] [--threads N] [--out FILE]\n", argv[0]); return 2; }
    }
    if (quick) { W = 96; H = 72; gt_spp = 32; }
    if (full) { W = 640; H = 480; gt_spp = 1024; }
    csv = fopen(out_path, "w");
    if (!csv) { fprintf(stderr, "cannot write %s\n", out_path); return 1; }
    fprintf(csv, "scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,mode,rays,camera_rays,speedup\n");
    printf("fovpt benchmark: %ux%u, ground truth %u spp (path) / 64 spp (Whitted), one thread per method\n", W, H, gt_spp);
    for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
        pt_scene S;
        size_t np = (size_t)W * H;
        float *ref_p = (float *)malloc(np * 12u), *ref_w = (float *)malloc(np * 12u), *img = (float *)malloc(np * 12u);
        float *ecc = (float *)malloc(np * 4u);
        if ((quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) || only_tp) continue;
        if (pt_scene_make(&S, sc) != 0) { fprintf(stderr, "scene %s failed\n", pt_scene_names[sc]); return 1; }
        S.cam.width = W; S.cam.height = H;
        for (gi = 0; gi < 2; ++gi) {
            fov_gaze g;
            fovpt_config base = fovpt_config_default(), c;
            fovpt_stats st;
            fov_ecc_model em;
            double t_u4 = 0.0, t;
            uint32_t x, y, m;
            static const char *const names[] = { "uniform4", "uniform1", "layers", "layers_diam", "zones", "whitted1", "selective", "jin" };
            uint64_t cam_rays[8];
            g.x = gi ? 0.08f * (float)W : 0.5f * (float)W;
            g.y = gi ? 0.08f * (float)H : 0.5f * (float)H;
            fovpt_ecc_init(&em, NULL, S.cam.fov_y_deg, W, H, g);
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x) ecc[(size_t)y * W + x] = fovpt_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
            c = base; c.spp = gt_spp; c.seed = 777;
            t = render(&S, &c, g, ref_p, &st, threads);
            printf("%-9s %-6s ground truth (path, %u spp): %.0f ms\n", pt_scene_names[sc], gi ? "corner" : "centre", gt_spp, t);
            c = base; c.mode = FOVPT_MODE_WHITTED; c.spp = 64; c.seed = 777;
            render(&S, &c, g, ref_w, &st, threads);
            for (m = 0; m < 8; ++m) {
                double ps[5];
                int whitted = m >= 5;
                c = base;
                if (whitted) c.mode = FOVPT_MODE_WHITTED;
                switch (m) {
                case 0: c.spp = 4; break;
                case 1: c.spp = 1; break;
                case 2: c.method = FOVPT_METHOD_LAYERS; break;
                case 3: c.method = FOVPT_METHOD_LAYERS; fovpt_layers_preset(&c.layers, FOVPT_LAYERS_KTH_DIAMETER); break;
                case 4: c.method = FOVPT_METHOD_ZONES; c.spp = 4; break;
                case 5: c.spp = 1; break;
                case 6: c.method = FOVPT_METHOD_SELECTIVE; break;
                default: c.method = FOVPT_METHOD_JIN; break;
                }
                t = render(&S, &c, g, img, &st, 1);
                if (m == 0) t_u4 = t;
                cam_rays[m] = st.camera_rays;
                psnr_fields(img, whitted ? ref_w : ref_p, ecc, np, ps);
                fprintf(csv, "%s,%s,%s,default,%.0f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%s,%llu,%llu,%.3f\n", pt_scene_names[sc], names[m],
                        gi ? "corner" : "centre", (double)st.rays / (t * 1e-3), t, ps[0], ps[1], ps[2], ps[3], ps[4],
                        whitted ? "whitted" : "path", (unsigned long long)st.rays, (unsigned long long)st.camera_rays, t_u4 / t);
                printf("  %-12s %9.1f ms %6.2f Mrays/s  PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f  speedup %.2f\n", names[m], t,
                       (double)st.rays / (t * 1e3), ps[0], ps[1], ps[2], ps[3], ps[4], t_u4 / t);
            }
            /* equal ray budget: UNIFORM at the camera-ray count of each foveated method */
            for (m = 2; m < 8; ++m) {
                double ps[5];
                uint32_t spp = (uint32_t)((double)cam_rays[m] / (double)np + 0.5);
                int whitted = m >= 5;
                if (m == 5) continue;
                if (!full && m == 3) continue;
                if (spp < 1) spp = 1;
                c = base;
                c.spp = spp;
                if (whitted) c.mode = FOVPT_MODE_WHITTED;
                t = render(&S, &c, g, img, &st, 1);
                psnr_fields(img, whitted ? ref_w : ref_p, ecc, np, ps);
                fprintf(csv, "%s,uniform_eq,%s,eqrays_%s,%.0f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%s,%llu,%llu,%.3f\n", pt_scene_names[sc],
                        gi ? "corner" : "centre", names[m], (double)st.rays / (t * 1e-3), t, ps[0], ps[1], ps[2], ps[3], ps[4],
                        whitted ? "whitted" : "path", (unsigned long long)st.rays, (unsigned long long)st.camera_rays, t_u4 / t);
                printf("  uniform_eq(%s, %u spp) %8.1f ms PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f\n", names[m], spp, t, ps[0], ps[1],
                       ps[2], ps[3], ps[4]);
            }
            fflush(csv);
        }
        pt_scene_free(&S);
        free(ref_p); free(ref_w); free(img); free(ecc);
    }
    if (!quick) throughput_rows(csv, W, H);
    fclose(csv);
    printf("wrote %s (%.0f s)\n", out_path, (now_ms() - t_start) * 1e-3);
    /* plots next to the CSV: pt_<scene>.png, speed-up over uniform4 against fovea PSNR (f1)
       and near-periphery PSNR (f4), every method, both gazes */
    if (!only_tp && system("command -v gnuplot > /dev/null 2>&1") == 0) {
        FILE *gp = popen("gnuplot", "w");
        const char *slash = strrchr(out_path, '/');
        int dirlen = slash ? (int)(slash - out_path + 1) : 0;
        if (gp) {
            for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
                const char *nm = pt_scene_names[sc];
                if (quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) continue;
                fprintf(gp, "set terminal pngcairo size 900,500; set output '%.*spt_%s.png'\n", dirlen, out_path, nm);
                fprintf(gp, "set datafile separator ','; set grid; set key bottom right\n");
                fprintf(gp, "set title '%s: speed-up over uniform 4 spp vs PSNR (%ux%u; default budgets)'\n", nm, W, H);
                fprintf(gp, "set xlabel 'time of uniform4 / time of the method (same run, one thread)'; set ylabel 'PSNR (dB)'\n");
                fprintf(gp, "plot '%s' every ::1 using ((strcol(1) eq '%s' && strcol(4) eq 'default') ? $15 : 1/0):7:(sprintf('%%s %%s', strcol(2), strcol(3))) "
                            "with labels point pt 7 offset 0.5,0.5 font ',7' title 'fovea (f1)', "
                            "'' every ::1 using ((strcol(1) eq '%s' && strcol(4) eq 'default') ? $15 : 1/0):10 with points pt 6 title 'near periphery (f4)'\n",
                        out_path, nm, nm);
            }
            pclose(gp);
            printf("plots next to %s: pt_<scene>.png\n", out_path);
        }
    } else if (!only_tp) {
        printf("gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    return 0;
}
