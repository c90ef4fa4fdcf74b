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

import csv
import functools
from pathlib import Path

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


#: The stored quadratures (tests/reference/j_integrals_mpmath.py writes them from :func:`j_integrals_mp_computed`).
STORED = Path(__file__).resolve().parent / "reference" / "j_integrals_mpmath.csv"


@functools.cache
def _stored() -> dict[tuple[float, float], tuple[mp.mpf, mp.mpf, mp.mpf]]:
    """{(n, Abar): (J0, Jc1, J1)} of the stored table, parsed at 50 digits (the table keeps 45)."""
    with STORED.open(newline="") as handle, mp.workdps(50):
        return {(float(row["n"]), float(row["Abar"])): (mp.mpf(row["J0"]), mp.mpf(row["Jc1"]), mp.mpf(row["J1"]))
                for row in csv.DictReader(handle)}


def j_integrals_mp(Abar: float, n: float) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """(J0, Jc1, J1) at ``DIGITS`` significant digits: the stored quadrature where (n, Abar) is a row of
    :data:`STORED` (the points of tests/core/test_integrals.py, whose stored-reference test recomputes a sample of
    them), else :func:`j_integrals_mp_computed`."""
    stored = _stored().get((float(n), float(Abar)))
    return stored if stored is not None else j_integrals_mp_computed(Abar, n)


@functools.cache
def j_integrals_mp_computed(Abar: float, n: float) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """(J0, Jc1, J1) at ``DIGITS`` significant digits for the Gent–Schultz law (the quadrature of the docstring)."""
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


def rate_dependent_jkr_pulloff_mp(base_offset: float, speed_group: float, n: float,
                                  start_radius: float | None = None) -> tuple[mp.mpf, mp.mpf]:
    """(most tensile force, base offset there) of a rigidly held JKR contact withdrawn at constant speed, h1 = 0.

    Derived here independently of the package. In the units a_o (radius), a_o^2/R (displacement)
    and E* a_o^3/R (force), JKR (Eqs. 4, 5) with w/w0 = Phi reads d = a^2 - sqrt(Phi a) and
    P = 2 a d - (2/3) a^3, so Phi = (a^2 - d)^2/a. The Gent–Schultz law (Eqs. 73–75), Phi = 1 +
    |x|^n opening and 1/(1 + x^n) closing with x = (da/dt)/v0, gives x = -(Phi - 1)^(1/n) for Phi >= 1
    and (1/Phi - 1)^(1/n) below. A displacement ramp d = base_offset - T, T = V t R/a_o^2, makes
    da/dT = x a_o/(V/v0 R) = x/G with G = (V/v0)/c_o = ``speed_group``. From the static contact
    (Phi = 1: a^2 - sqrt(a) = base_offset, a > 4^(-2/3)), or from a = ``start_radius`` if given, the ODE is
    integrated with mpmath's Taylor method (tol 1e-16 at 20 digits) and the force minimum located where
    dP/dT = 2 a'(d - a^2) - 2 a = 0.
    """
    with mp.workdps(20):
        d0, g, inv_n = mp.mpf(base_offset), mp.mpf(speed_group), 1 / mp.mpf(n)
        a0 = mp.findroot(lambda a: a * a - mp.sqrt(a) - d0, mp.mpf(2)) if start_radius is None else mp.mpf(start_radius)

        def rate(t, a):
            phi = (a * a - (d0 - t)) ** 2 / a
            return (-((phi - 1) ** inv_n) if phi >= 1 else (1 / phi - 1) ** inv_n) / g

        a_of = mp.odefun(rate, 0, a0, tol=mp.mpf(10) ** -16)

        def force_slope(t):
            a = a_of(t)
            return 2 * rate(t, a) * ((d0 - t) - a * a) - 2 * a

        step, t = (d0 + 1) / 80, mp.mpf(0)
        while force_slope(t + step) < 0:  # the force falls until its minimum (before the contact is lost)
            t += step
        t_min = mp.findroot(force_slope, (t, t + step), solver="anderson")
        a = a_of(t_min)
        return 2 * a * (d0 - t_min) - 2 * a**3 / 3, d0 - t_min
