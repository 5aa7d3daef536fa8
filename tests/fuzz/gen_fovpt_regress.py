#!/usr/bin/env python3
"""Writes the fovpt fuzz regression inputs of issue 10 (tests/fuzz/regress/fovpt/) in the byte
layout that tests/fuzz/fuzz_fovpt.c reads. Run from the repository root:
    python3 tests/fuzz/gen_fovpt_regress.py
F1_camera_ray.bin   1x1 camera, up (3e38, 3e38, 3e38), image point (1e30, 0.5): FOV_OK with a
                    non-unit ray before the fix
F7_axis_face.bin    triangle (-2,-2,0) (1,-2,0) (1,1,0), bvh_min_prims 1, ray from (1,0,1) along
                    -z (lying in the box's max face x = 1): brute force t = 1, the BVH missed
T14_tiny_direction.bin  a strip 2^-100 thin, rays with a subnormal direction component: the
                    BVH of 0.8.0 lost the brute-force hits (1/d overflowed)
F7_box_margin.bin   square [-1,0]^2 at z = -1 (two triangles), ray from (2.558, 1.0000001,
                    1.0000001) along (-1.558, -0.5, -1): brute force t = 2, the BVH missed
"""
import os
import struct

def u8(v): return bytes([v & 255])
def grid(x):            # fz_coord, grid branch: value = 0.25 * (pick - 16) at scale 1
    p = int(round(x * 4)) + 16
    assert 0 <= p <= 32
    return u8(0) + u8(p)
def raw_coord(x):       # fz_coord, raw branch
    return u8(255) + struct.pack('<f', x)
def ffloat_raw(x):      # fz_float, raw branch
    return u8(200) + struct.pack('<f', x)
def ffloat_edge0():     # fz_float, edge value 0.0
    return u8(224)
def ffloat_hi():        # fz_float, unit range at its top (hi)
    return u8(0) + struct.pack('<H', 65535)

def header(tris):
    b = u8(len(tris) - 1) + u8(0) + u8(1) + u8(255)   # nt, no shapes, scale 1, no offset
    for t in tris:
        b += u8(0)                                    # mode 0: coordinates as given
        for v in t:
            for x in v: b += grid(x)
    for _ in range(3): b += u8(0) + u8(255)           # Lambert materials, no emission
    b += u8(0)                                        # mesh material 0
    b += u8(0) + u8(0) + u8(1) + u8(255)              # bvh_min_prims 1, leaf default, bins default, skip degenerate
    return b

def axis_ray(o, axis, sign_neg):
    b = u8(3)                                         # mode 3: along an axis
    for x in o: b += grid(x)
    return b + u8(axis) + u8(1 if sign_neg else 0) + u8(255) + u8(255)   # tmin 0, tmax FLT_MAX

out = os.path.join('tests', 'fuzz', 'regress', 'fovpt')
os.makedirs(out, exist_ok=True)

# F7a
b = header([((-2, -2, 0), (1, -2, 0), (1, 1, 0))]) + u8(0) + axis_ray((1, 0, 1), 2, True)
open(os.path.join(out, 'F7_axis_face.bin'), 'wb').write(b)

# F7b
b = header([((-1, -1, -1), (0, -1, -1), (0, 0, -1)), ((-1, -1, -1), (0, 0, -1), (-1, 0, -1))]) + u8(0)
b += u8(5)                                            # mode 5: raw origin and direction
for x in (2.558, 1.0000001, 1.0000001): b += raw_coord(x)
for x in (-1.558, -0.5, -1.0): b += ffloat_raw(x)
b += u8(255) + u8(255)
open(os.path.join(out, 'F7_box_margin.bin'), 'wb').write(b)

# T14: a strip 2^-100 thin beside the origin (two triangles, raw coordinates), rays with a
# subnormal direction component and a near-parallel course: fovpt 0.8.0's BVH lost these hits
e = 2.0 ** -100
b = u8(1) + u8(0) + u8(1) + u8(255)                  # 2 triangles, no shapes, scale 1, no offset
for t in (((0, -1000, -1000), (0, 1000, -1000), (-e, 0, 1000)),
          ((0, 2000, -1000), (0, 4000, -1000), (-e, 3000, 1000))):
    b += u8(0)                                        # mode 0: coordinates as given
    for v in t:
        for x in v: b += raw_coord(x)
for _ in range(3): b += u8(0) + u8(255)
b += u8(0)                                            # mesh material 0
b += u8(0) + u8(0) + u8(1) + u8(255)                  # bvh_min_prims 1, leaf default, bins default, skip degenerate
b += u8(0)                                            # 8 rays
dx = struct.unpack('<f', struct.pack('<I', 0x00200001))[0]
o0 = struct.unpack('<f', struct.pack('<I', struct.unpack('<I', struct.pack('<f', 2.0 ** -121))[0] + 1))[0]
for k in range(8):
    o = struct.unpack('<f', struct.pack('<I', struct.unpack('<I', struct.pack('<f', o0))[0] + 3 * k))[0]
    b += u8(5)                                        # mode 5: raw origin and direction
    for x in (o, 0.0, 0.0): b += raw_coord(x)
    for x in (dx, 0.0, 1.0): b += ffloat_raw(x)
    b += u8(0) + ffloat_raw(-2000.0) + u8(0) + ffloat_raw(2000.0)   # tmin -2000, tmax 2000
open(os.path.join(out, 'T14_tiny_direction.bin'), 'wb').write(b)

# F1: a harmless scene and 8 rays, then the camera
b = header([((-1, -1, 2), (1, -1, 2), (0, 1, 2))]) + u8(0)
for _ in range(8): b += axis_ray((0, 0, 0), 2, False)
b += struct.pack('<I', 0) + u8(0)                     # 1 x 1 image
for k in range(3):
    b += ffloat_edge0()                               # pos[k] = 0
    b += ffloat_hi() if k == 2 else ffloat_edge0()    # target = (0, 0, 1)
    b += ffloat_raw(3e38)                             # up[k] = 3e38
b += ffloat_edge0() + u8(255)                         # fov 0 (default 60), symmetric
b += ffloat_raw(1e30) + ffloat_raw(0.5)               # the image point (1e30, 0.5)
open(os.path.join(out, 'F1_camera_ray.bin'), 'wb').write(b)
print('wrote', sorted(os.listdir(out)))
