#!/usr/bin/env python3
"""gen_fovlp.py - writes the seed corpus (tests/fuzz/corpus/fovlp/) and the regression inputs
of issue 10 (tests/fuzz/regress/fovlp/) for fuzz_fovlp.c.

The byte layout is the harness's reading order (the comment at the top of fuzz_fovlp.c);
each Enc method mirrors one reader of tests/fuzz/fuzz_common.h. Run from the repository root:
    python3 tests/fuzz/gen_fovlp.py
"""
import os
import struct

EDGE = dict(zero=0, mzero=1, fmax=2, mfmax=3, fmin=4, tiny=5, big=6, mbig=7)


class Enc:
    def __init__(self):
        self.b = bytearray()

    def u8(self, v):
        self.b.append(v & 0xFF)

    def u16(self, v):
        self.b += struct.pack('<H', v & 0xFFFF)

    def f(self, lo, hi, v):
        """fz_float in range: selector < 192, then 16 bits"""
        self.u8(0)
        self.u16(0 if hi == lo else round((v - lo) / (hi - lo) * 65535))

    def raw(self, v):
        """fz_raw_float: 4 bytes of bits"""
        self.b += struct.pack('<f', v)

    def fraw(self, v):
        """fz_float giving raw bits: selector 192"""
        self.u8(192)
        self.raw(v)

    def edge(self, name):
        """fz_float giving an edge value: selector 224 + index"""
        self.u8(224 + EDGE[name])

    def nan(self):
        self.u8(248)

    def inf(self):
        self.u8(249)


def config(e, preset=2, w=16, h=12, a=0, b=0, a_fields=(), taa=None, blend=None, acuity=None):
    """a_fields: callables writing the flag-A fields in bit order; taa: dict of taa fields;
    acuity (flag B bit 4): (mar0, slope, quality, tan_half_y or None)"""
    e.u8(preset)
    e.u8(w - 1)
    e.u8(h - 1)
    e.u8(a)
    for fn in a_fields:
        fn(e)
    e.u8(b)
    if b & 2:
        mode, s, t = blend
        e.u8(mode); e.f(0, 1, s); e.f(0, 1, t)
    if b & 8:
        e.u8(taa.get('phases', 0)); e.u8(taa.get('halton', 0)); e.u8(taa.get('max_age', 0))
        e.u8(taa.get('clamp', 0))
        e.f(0.5, 3, taa.get('gamma', 1.0)); e.f(0, 0.1, taa.get('tol', 0.02))
        e.f(0, 10, taa.get('reset', 2.0)); e.f(0, 1, taa.get('periphery', 1 / 3))
        e.u8(taa.get('jitter_moving', 0)); e.u8(taa.get('thesis_moving', 0))
    if b & 16:
        mar0, slope, quality, tan = acuity
        e.f(0, 4, mar0); e.f(0, 4, slope); e.f(0, 4, quality)
        e.u8(0 if tan is None else 1)
        if tan is not None:
            e.f(0.05, 3, tan)


def frame(e, w, h, gx, gy, cam=0, cam_args=(), shade=0, shade_args=(), dmode=0, dconst=5.0,
          splits=(3, 5, 4, 2, 6, 7), edits=(), queries=()):
    e.f(-4, w + 4, gx)
    e.f(-4, h + 4, gy)
    e.u8(cam)
    if cam == 2:
        for v in cam_args[:3]:
            e.f(-0.2, 0.2, v)
        e.f(-0.05, 0.05, cam_args[3])
    elif cam == 3:
        for v in cam_args[:3]:
            e.f(-1e3, 1e3, v)
        e.f(0.1, 2, cam_args[3])
        for v in (list(cam_args[4:13]) + [0.0] * 9)[:9]:   # right[k], up[k], fwd[k] offsets
            v(e) if callable(v) else e.f(-0.1, 0.1, v)
    e.u8(shade)
    if shade == 4:
        for v in shade_args:
            e.raw(v)
    elif shade == 5:
        e.raw(shade_args[0])
    e.u8(dmode)
    if dmode == 4:
        e.f(0.1, 100, dconst)
    for s in splits:
        e.u8(s)
    # history edits: (bit, index, value)
    bits = 0
    for b, _, _ in edits:
        bits |= b
    e.u8(bits)
    for b in (2, 4, 8):
        for bb, idx, val in edits:
            if bb == b:
                e.u16(idx)
                e.u8(val) if b == 8 else e.raw(val)
    e.u8(len(queries))
    for q in queries:
        q(e)


def query(x, y, r, u, v, phase, w, h, lpw=64, lph=64):
    diag = (w * w + h * h) ** 0.5

    def fn(e):
        x(e, -2 * w, 3 * w) if callable(x) else e.f(-2 * w, 3 * w, x)
        y(e, -2 * h, 3 * h) if callable(y) else e.f(-2 * h, 3 * h, y)
        r(e) if callable(r) else e.f(0, 4 * diag, r)
        e.f(-4, lpw + 4, u)
        e.f(-4, lph + 4, v)
        e.u8(phase)
    return fn


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'wb') as fh:
        fh.write(bytes(data))


def corpus():
    out = {}
    # 1. C Fov defaults, TAA on, 4 still frames of smooth colours, queries
    e = Enc()
    config(e, preset=2, w=24, h=16, b=4)
    e.u8(3)
    for k in range(4):
        frame(e, 24, 16, 12.3 + k * 0.1, 8.1, cam=1, shade=0,
              queries=[query(5.0 + k, 3.0, 7.0, 10.0, 20.0, k, 24, 16)])
    out['c_fov_still'] = e.b
    # 2. plain log-polar (Fov), moving camera, variance clip, blend on
    e = Enc()
    config(e, preset=0, w=24, h=20, b=2 | 4 | 8, blend=(1, 0.1, 0.5), taa=dict(clamp=2, max_age=8))
    e.u8(4)
    for k in range(5):
        frame(e, 24, 20, 12.0, 10.0, cam=2, cam_args=(0.05, 0.0, 0.01, 0.01), shade=0, dmode=0)
    out['fov_moving_clip'] = e.b
    # 3. K Fov (alpha 3), gaze jumps, AABB clamp, huge colours
    e = Enc()
    config(e, preset=1, w=20, h=20, b=4 | 8, taa=dict(clamp=1))
    e.u8(3)
    for k, g in enumerate([(2.0, 3.0), (18.0, 17.0), (10.0, 10.0), (0.0, 20.0)]):
        frame(e, 20, 20, g[0], g[1], cam=1, shade=1 if k % 2 else 0, dmode=1)
    out['k_fov_jumps_huge'] = e.b
    # 4. C K Fov with a display geometry, NaN / inf colours and depths, thesis moving
    e = Enc()
    config(e, preset=3, w=24, h=18, a=128, b=4 | 8, a_fields=[lambda e: (e.u8(1), e.f(0.05, 1, 0.25), e.f(100, 2000, 600))],
           taa=dict(thesis_moving=1, periphery=0.2))
    e.u8(4)
    for k in range(5):
        frame(e, 24, 18, 12.0, 9.0, cam=2, cam_args=(0.02, 0.01, 0.0, 0.0), shade=3, dmode=2)
    out['c_k_fov_display_nan'] = e.b
    # 5. zero config with sigma / alpha / aspect given, a strip screen, hostile queries
    e = Enc()
    config(e, preset=4, w=24, h=2, a=1 | 2 | 16, b=0,
           a_fields=[lambda e: e.f(0.3, 4, 0.5), lambda e: e.f(0.25, 8, 2.5), lambda e: e.f(0.1, 4, 2.0)])
    e.u8(1)
    frame(e, 24, 2, 23.0, 1.0, cam=0, shade=4, shade_args=(1e30, -2.5, 3e38, 0.0),
          queries=[query(lambda e, lo, hi: e.edge('fmax'), lambda e, lo, hi: e.edge('mfmax'),
                         lambda e: e.edge('big'), 1e6, -3.0, 200, 24, 2),
                   query(lambda e, lo, hi: e.nan(), 1.0, lambda e: e.inf(), 0.0, 0.0, 1, 24, 2)])
    out['strip_hostile_queries'] = e.b
    # 6. a 1x1 screen, no disc, TAA with every field at an edge
    e = Enc()
    config(e, preset=0, w=1, h=1, b=4 | 8, taa=dict(phases=255, halton=200, max_age=255, clamp=3, gamma=3.0))
    e.u8(2)
    for k in range(3):
        frame(e, 1, 1, 0.5, 0.5, cam=3, cam_args=(1.0, -2.0, 3.0, 0.5, 0.05, 0.0, 0.01), shade=5, shade_args=(0.25,))
    out['one_pixel'] = e.b
    # 7. a hostile camera (right of length 1e30), history edits (NaN colour, inf depth, age 255,
    #    a reset), moving camera otherwise
    e = Enc()
    config(e, preset=2, w=16, h=16, b=4 | 8, taa=dict(clamp=0))
    e.u8(3)
    frame(e, 16, 16, 8.0, 8.0, cam=1, shade=0, dmode=4)
    frame(e, 16, 16, 8.0, 8.0, cam=2, cam_args=(0.1, 0.0, 0.0, 0.0), shade=0, dmode=4,
          edits=[(2, 100, float('nan')), (4, 37, float('inf')), (8, 12, 255)])
    frame(e, 16, 16, 8.0, 8.0, cam=3, cam_args=(0.0, 0.0, 0.0, 0.5, lambda e: e.edge('big')), shade=0, dmode=4)
    frame(e, 16, 16, 8.0, 8.0, cam=1, shade=0, dmode=4, edits=[(1, 0, 0), (2, 5, 3e38)])
    out['hostile_camera_history_edits'] = e.b
    # 8. fovlp_config_acuity (issue 13): a dense monitor (0.05 mm pixels at 2 m: 698 ppd, the
    #    eye needs no pixel of its own), default eye, TAA, still then moving camera
    e = Enc()
    config(e, preset=4, w=24, h=20, a=128, b=4 | 16,
           a_fields=[lambda e: (e.u8(1), e.f(0.05, 1, 0.05), e.f(100, 2000, 2000))],
           acuity=(0.0, 0.0, 1.0, None))
    e.u8(3)
    for k in range(4):
        frame(e, 24, 20, 12.0 + k, 10.0, cam=1 if k < 2 else 2, cam_args=(0.02, 0.0, 0.0, 0.0),
              shade=0, queries=[query(3.0, 4.0, 9.0, 2.0, 5.0, k, 24, 20)])
    out['acuity_dense_monitor'] = e.b
    return out


def regress():
    out = {}
    # F8: a still camera with frame colours 3e38 then -3e38 (no clamp): hist + (cur - hist) / age
    # overflowed to -inf in all of the history
    e = Enc()
    config(e, preset=0, w=8, h=8, b=4)
    e.u8(1)   # 2 frames
    frame(e, 8, 8, 4.0, 4.0, cam=1, shade=5, shade_args=(3e38,))
    frame(e, 8, 8, 4.0, 4.0, cam=1, shade=5, shade_args=(-3e38,))
    out['F8_taa_overflow'] = e.b
    # F9: fovlp_spacing(FLT_MAX) returned FOV_OK with an infinite spacing
    e = Enc()
    config(e, preset=2, w=16, h=12, b=0)
    e.u8(0)   # 1 frame
    frame(e, 16, 12, 8.0, 6.0, cam=0, shade=0,
          queries=[query(3.0, 4.0, lambda e: e.edge('fmax'), 5.0, 5.0, 0, 16, 12)])
    out['F9_spacing_flt_max'] = e.b
    return out


if __name__ == '__main__':
    for name, data in corpus().items():
        write('tests/fuzz/corpus/fovlp/%s.bin' % name, data)
    for name, data in regress().items():
        write('tests/fuzz/regress/fovlp/%s.bin' % name, data)
    print('wrote %d corpus and %d regression inputs' % (len(corpus()), len(regress())))
