#!/usr/bin/env python3
"""Writes assets/meshes/vase.obj: the tabletop suite's zero-shot mesh object (issue 15).

A lathed vase, 16 cm tall, with an oval, slightly irregular cross-section (seeded radial
noise), so it is none of the suite's primitive shapes. Metres, +z up, base at z = 0.
Usage: python3 scripts/make_vase_obj.py > assets/meshes/vase.obj
"""
import math
import random

HEIGHT = 0.16
RINGS = 12
SEGMENTS = 24
rng = random.Random(15)
noise = [1.0 + rng.uniform(-0.06, 0.06) for _ in range(SEGMENTS)]


def radius(z):
    # 3.2 cm at the base, 4.6 cm at 45 % of the height, 3.0 cm at the rim
    t = z / HEIGHT
    return 0.032 + 0.014 * math.sin(math.pi * min(1.0, t / 0.9)) - 0.002 * t


print("# simhuman zero-shot vase, written by scripts/make_vase_obj.py")
for i in range(RINGS + 1):
    z = HEIGHT * i / RINGS
    for j in range(SEGMENTS):
        a = 2 * math.pi * j / SEGMENTS
        r = radius(z) * noise[j]
        print(f"v {r * math.cos(a):.5f} {0.8 * r * math.sin(a):.5f} {z:.5f}")
print(f"v 0 0 0")
print(f"v 0 0 {HEIGHT:.5f}")
bottom = (RINGS + 1) * SEGMENTS + 1
top = bottom + 1
for i in range(RINGS):
    for j in range(SEGMENTS):
        a = i * SEGMENTS + j + 1
        b = i * SEGMENTS + (j + 1) % SEGMENTS + 1
        print(f"f {a} {b} {b + SEGMENTS} {a + SEGMENTS}")
for j in range(SEGMENTS):
    a, b = j + 1, (j + 1) % SEGMENTS + 1
    print(f"f {bottom} {b} {a}")
    ta, tb = RINGS * SEGMENTS + a, RINGS * SEGMENTS + b
    print(f"f {top} {ta} {tb}")
