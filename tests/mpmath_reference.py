"""High-precision reference values of the J-integrals, computed independently of the package.

The integrals are evaluated straight from their definitions, Eqs. (28), (29) and (36) of
Argatov, Papangelo & Ciavarella, "An asymptotic model of vibroadhesion", with the
Gent–Schultz law of Eqs. (73)–(75) written out here again in mpmath arithmetic:

    J0  = 1/pi  int_0^pi sqrt(f(A cos x)) dx
    Jc1 = 2/pi  int_0^pi sqrt(f(A cos x)) cos x dx
    J1  = 2/pi  int_0^pi sqrt(f(A cos x)) sin^2 x dx

with f(s) = 1 + |s|^n for s < 0 (opening) and 1/(1 + s^n) for s > 0 (closing).

For small A, Jc1 is the O(A^n) remainder of two O(1) halves that cancel; the working
precision is raised by n*log10(1/A) digits to keep DIGITS significant digits in it.

The integrand is not smooth at x = pi/2 (|cos x|^n, n not an integer) and changes over a
boundary layer of width ~1/A there, so the interval is split at pi/2 and at the geometric
sequence pi/2 +- 10^k / A, on which tanh-sinh quadrature converges fast.
"""

from __future__ import annotations

import functools

import mpmath as mp

DIGITS = 30


def _breakpoints(Abar: mp.mpf) -> list:
    half_pi = mp.pi / 2
    points = [mp.mpf(0), half_pi, mp.pi]
    if Abar > 1:
        scale = 1 / Abar
        while scale < half_pi / 2:
            points += [half_pi - scale, half_pi + scale]
            scale *= 10
    return sorted(points)


@functools.cache
def j_integrals_mp(Abar: float, n: float) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """(J0, Jc1, J1) at ``DIGITS`` significant digits for the Gent–Schultz law."""
    # Jc1 is a difference of two O(1) halves that cancel to O(A^n) for small A: carry
    # n*log10(1/A) guard digits so that the result still has DIGITS significant digits.
    guard = 10 + (int(n * -mp.log10(Abar)) + 1 if 0 < Abar < 1 else 0)
    with mp.workdps(DIGITS + guard):
        a, nn = mp.mpf(Abar), mp.mpf(n)

        def sqrt_f(x):
            s = a * mp.cos(x)
            if s < 0:
                return mp.sqrt(1 + (-s) ** nn)
            return 1 / mp.sqrt(1 + s**nn)

        pts = _breakpoints(a)
        j0 = mp.quad(sqrt_f, pts) / mp.pi
        jc1 = 2 * mp.quad(lambda x: sqrt_f(x) * mp.cos(x), pts) / mp.pi
        j1 = 2 * mp.quad(lambda x: sqrt_f(x) * mp.sin(x) ** 2, pts) / mp.pi
        return +j0, +jc1, +j1
