#!/usr/bin/python3
"""Reference values for core/ar (LSF conversion, Burg, all-pole filtering).

Run with Debian's python3 (numpy, scipy): /usr/bin/python3 tests/golden/ar_golden.py
Writes tests/golden/ar/*.npy (float64, C order). Everything is seeded.

The LSF reference follows MATLAB's poly2lsf / lsf2poly with np.roots, i.e. generic polynomial
root finding, a different route from the C++ unit-circle search it checks.
"""
import os

import numpy as np
from scipy.signal import lfilter

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ar")


def save(name, array):
    np.save(os.path.join(OUT, name), np.ascontiguousarray(array, dtype=np.float64))


def poly2lsf(a):
    """MATLAB poly2lsf: LSFs of a stable A(z) = a[0] + a[1] z^-1 + ... (a[0] divided out)."""
    a = np.asarray(a, dtype=float) / a[0]
    if np.max(np.abs(np.roots(a))) >= 1.0:
        raise ValueError("unstable polynomial")
    p = len(a) - 1
    a1 = np.concatenate([a, [0.0]])
    a2 = a1[::-1]
    p1, q1 = a1 - a2, a1 + a2
    if p % 2:  # odd order: z = +1 and z = -1 are roots of the difference filter
        pp, _ = np.polydiv(p1, [1.0, 0.0, -1.0])
        qq = q1
    else:  # even order: z = 1 of the difference filter, z = -1 of the sum filter
        pp, _ = np.polydiv(p1, [1.0, -1.0])
        qq, _ = np.polydiv(q1, [1.0, 1.0])
    angles = np.concatenate([np.angle(np.roots(pp)), np.angle(np.roots(qq))])
    return np.sort(angles[angles > 0])


def lsf2poly(lsf):
    """MATLAB lsf2poly."""
    lsf = np.asarray(lsf, dtype=float)
    p = len(lsf)
    z = np.exp(1j * lsf)
    rq, rp = z[0::2], z[1::2]
    q = np.real(np.poly(np.concatenate([rq, rq.conj()])))
    pp = np.real(np.poly(np.concatenate([rp, rp.conj()])))
    if p % 2:
        p1, q1 = np.convolve(pp, [1.0, 0.0, -1.0]), q
    else:
        p1, q1 = np.convolve(pp, [1.0, -1.0]), np.convolve(q, [1.0, 1.0])
    return 0.5 * (p1 + q1)[:-1]


def random_stable_poly(rng, order, r_min=0.3, r_max=0.97):
    """Real polynomial with conjugate pole pairs (plus one real pole for odd order) inside |z| < 1."""
    poles = []
    for _ in range(order // 2):
        r, w = rng.uniform(r_min, r_max), rng.uniform(0.05, np.pi - 0.05)
        poles += [r * np.exp(1j * w), r * np.exp(-1j * w)]
    if order % 2:
        poles.append(rng.uniform(-r_max, r_max))
    return np.real(np.poly(poles))


def burg(x, order):
    """MATLAB arburg, written out from its recursion (no mean removal, E0 = x'x / N)."""
    x = np.asarray(x, dtype=float)
    n = len(x)
    ef, eb = x.copy(), x.copy()
    a = np.array([1.0])
    e = x @ x / n
    for _ in range(order):
        efp, ebp = ef[1:], eb[:-1]
        k = -2.0 * (ebp @ efp) / (efp @ efp + ebp @ ebp)
        ef, eb = efp + k * ebp, ebp + k * efp
        a = np.concatenate([a, [0.0]]) + k * np.concatenate([[0.0], a[::-1]])
        e *= 1.0 - k * k
    return a, e


def cross_check_statsmodels(x, order, a, e):
    try:
        from statsmodels.regression.linear_model import burg as sm_burg
    except ImportError:
        print("statsmodels not installed: Burg reference not cross-checked against it")
        return
    rho, sigma2 = sm_burg(x, order, demean=False)
    coeff_err = np.max(np.abs(np.concatenate([[1.0], -np.asarray(rho)]) - a))
    print(f"statsmodels burg order {order}: max coefficient difference {coeff_err:.3g}, "
          f"variance {sigma2:.9g} vs {e:.9g}")
    assert coeff_err < 1e-8, "numpy Burg reference disagrees with statsmodels"


def lsf_cases(rng):
    for order in (5, 8, 13, 20):
        a = random_stable_poly(rng, order)
        lsf = poly2lsf(a)
        assert len(lsf) == order and np.all(np.diff(lsf) > 0)
        assert np.max(np.abs(lsf2poly(lsf) - a)) < 1e-9
        save(f"lsf_poly_order{order:02d}.npy", a)
        save(f"lsf_order{order:02d}.npy", lsf)


def burg_case(rng):
    a_true = random_stable_poly(rng, 5, r_min=0.6, r_max=0.95)
    x = lfilter([1.0], a_true, np.sqrt(0.7) * rng.standard_normal(20000))
    save("burg_x.npy", x)
    save("burg_true_a.npy", a_true)
    for order in (5, 8):
        a, e = burg(x, order)
        cross_check_statsmodels(x, order, a, e)
        save(f"burg_order{order}.npy", np.concatenate([a, [e]]))  # coefficients, then variance


def filter_case(rng):
    a = random_stable_poly(rng, 6, r_min=0.5, r_max=0.95)
    e = rng.standard_normal(2000)
    save("filter_a.npy", a)
    save("filter_e.npy", e)
    save("filter_y.npy", lfilter([1.0], a, e))


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = np.random.default_rng(20240611)
    lsf_cases(rng)
    burg_case(rng)
    filter_case(rng)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
