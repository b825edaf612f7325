#!/usr/bin/env python3
"""Reference profile of Schwarz's minimal surface spanning four edges of a
regular tetrahedron (the four-point sail of tests/form_finding).

Weierstrass representation with g(w) = w and f(w) = (1 - 14 w^4 + w^8)^(-1/2)
on the disc |w| < r0 = sqrt(2 - sqrt(3)), whose branch points map to the
corners. On the real axis the surface lies in the mirror plane through the
high diagonal: x(t) = int_0^t (1 - s^2) f(s) ds (along the diagonal) and
z(t) = int_0^t 2 s f(s) ds (height above the centre). Prints z/h at
x/d = k/40, k = 0..40 (d = x(r0), h = z(r0)), the table of the test.
Needs mpmath (pip install mpmath); not run by the tests.
"""
from mpmath import mp, mpf, sqrt, quad, findroot

mp.dps = 20
r0 = sqrt(2 - sqrt(3))


def f(w):
    return 1 / sqrt(1 - 14 * w**4 + w**8)


def diagonal(t):
    """(x, z) of the real-axis point t of the surface."""
    return (quad(lambda s: (1 - s**2) * f(s), [0, t]).real,
            quad(lambda s: 2 * s * f(s), [0, t]).real)


d, h = diagonal(r0)
profile = []
for k in range(41):
    frac = mpf(k) / 40
    if k in (0, 40):
        profile.append(float(frac))
        continue
    t = findroot(lambda t: diagonal(t)[0] - frac * d,
                 (mpf(0), r0 * (1 - mpf('1e-18'))), solver='illinois')
    profile.append(float(diagonal(t)[1] / h))
print(',\n'.join(', '.join('%.9f' % v for v in profile[k:k + 5])
                 for k in range(0, 41, 5)))
