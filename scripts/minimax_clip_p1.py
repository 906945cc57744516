#!/usr/bin/env python3
"""Minimax 3-segment piecewise-linear clip volume v(a) = Phi(a/0.2), a in [0, 0.5].

v is concave on [0, 0.5], so the best line on [l, r] is the chord shifted up by half the largest
chord gap E(l, r) (Chebyshev equioscillation at l, xi, r with v'(xi) = chord slope). Breakpoints are
codes of the input format (ClipInF = 12 fraction bits); a bisection on the target error E finds the
smallest E for which three greedy segments cover [0, 0.5]. Coefficients are printed as raw codes
with ClipCoefF = 18 fraction bits (value = c0 + c1*a on each segment), as used in
cmodel/blocks/gauss/clip.cpp. Run: python3 scripts/minimax_clip_p1.py
"""
import math

IN_F, COEF_F, SIGMA = 12, 18, 0.2
def v(a): return 0.5 * (1 + math.erf(a / (SIGMA * math.sqrt(2))))
def fit(l, r):
    m = (v(r) - v(l)) / (r - l)
    # v'(xi) = exp(-xi^2/(2 s^2)) / (s sqrt(2 pi)) = m
    xi = SIGMA * math.sqrt(max(0.0, -2 * math.log(m * SIGMA * math.sqrt(2 * math.pi))))
    e = (v(xi) - v(l) - m * (xi - l)) / 2
    return m, v(l) - m * l + e, e
END = 1 << (IN_F - 1)  # code of 0.5
def cover(target):
    bps, l = [], 0
    for _ in range(3):
        lo, hi = l + 1, END
        while lo < hi:  # largest r with E(l, r) <= target
            mid = (lo + hi + 1) // 2
            if fit(l / 2**IN_F, mid / 2**IN_F)[2] <= target: lo = mid
            else: hi = mid - 1
        bps.append(lo); l = lo
        if l >= END: return bps
    return None
lo, hi = 0.0, 0.05
for _ in range(60):
    mid = (lo + hi) / 2
    if cover(mid): hi = mid
    else: lo = mid
bps = cover(hi)
bps[-1] = END
edges = [0] + bps
print(f"target error {hi:.6e}")
for k in range(3):
    l, r = edges[k] / 2**IN_F, edges[k + 1] / 2**IN_F
    m, c, e = fit(l, r)
    print(f"segment {k}: a in [{edges[k]}, {edges[k+1]}) codes = [{l:.6f}, {r:.6f}) "
          f"c0 raw {round(c * 2**COEF_F)} c1 raw {round(m * 2**COEF_F)} err {e:.6e}")
