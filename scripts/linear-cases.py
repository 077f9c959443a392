#!/usr/bin/env python3
"""Write N line ∩ plane cases (JSON Lines) to stdout: the throughput file of
BENCHMARKS.md ("10⁶ linear cases"). Seeded: the same N gives the same bytes.

    scripts/linear-cases.py 1000000 > lp1m.jsonl
"""
import random
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000000
random.seed(7)


def r(a):
    return [round(random.uniform(-a, a), 6) for _ in range(3)]


out = sys.stdout
for i in range(n):
    o, d, po, u, v = r(100), r(1), r(100), r(1), r(1)
    out.write('{"id":"lp-%d","op":"intersect","objects":[{"type":"line","origin":%s,'
              '"dir":%s},{"type":"plane","origin":%s,"u":%s,"v":%s}]}\n'
              % (i, o, d, po, u, v))
