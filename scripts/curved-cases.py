#!/usr/bin/env python3
"""Write N curved cases (JSON Lines) to stdout: the thread-scaling file of
BENCHMARKS.md ("curved cases, 1 → 2 threads"). A seeded mix of lines against spheres,
tori and cylinders, and circles against planes and spheres, random 6-digit data.
Seeded: the same N gives the same bytes.

    scripts/curved-cases.py 4000 > curved4k.jsonl
"""
import random
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 4000
random.seed(11)


def r(a):
    return [round(random.uniform(-a, a), 6) for _ in range(3)]


def pos(lo, hi):
    return round(random.uniform(lo, hi), 6)


def line():
    return '{"type":"line","origin":%s,"dir":%s}' % (r(3), r(1))


def circle():
    return '{"type":"circle","center":%s,"radius":%s,"axis":%s}' % (r(1), pos(0.5, 2), r(1))


def surface(k):
    if k == 0:
        return '{"type":"sphere","center":%s,"radius":%s}' % (r(1), pos(0.5, 2))
    if k == 1:
        return '{"type":"torus","center":%s,"major":%s,"minor":%s,"axis":%s}' % (
            r(1), pos(1.5, 2.5), pos(0.3, 1), r(1))
    if k == 2:
        return '{"type":"cylinder","origin":%s,"radius":%s,"axis":%s,"height":[-3,3]}' % (
            r(1), pos(0.5, 2), r(1))
    return '{"type":"plane","normal":%s,"d":%s}' % (r(1), pos(-1, 1))


out = sys.stdout
for i in range(n):
    k = i % 5
    if k < 3:
        pair = (line(), surface(k))
    elif k == 3:
        pair = (circle(), surface(3))
    else:
        pair = (circle(), surface(0))
    out.write('{"id":"cv-%d","op":"intersect","objects":[%s,%s]}\n' % (i, pair[0], pair[1]))
