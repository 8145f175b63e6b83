"""W1 tower(N) with python-flint (fmpq_mpoly): the paper's normal form A(c) + s·B(c).

For every 1 <= m, n <= N: expand P_{m,n} = Re(Z^m e^{-in theta}) and Q_{m,n} = Im(...) with
symbolic M, omega; form {P, 2MI·H} (H scaled by the constant 2MI so that everything is a
polynomial); restrict to p_theta = m I omega / n; test for zero.
"""
import sys
import time

import flint

N = int(sys.argv[1]) if len(sys.argv) > 1 else 8
SINGLE = len(sys.argv) > 2 and sys.argv[2] == "single"
ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "c", "s", "px", "py", "pt", "M", "w", "I"), "lex")
x, y, c, s, px, py, pt, M, w, I = ctx.gens()
G = I * (px**2 + py**2) + M**2 * w**2 * I * (x**2 + y**2) + M * pt**2  # 2MI·H
A = px - M * w * y  # Z = A + iB
B = py + M * w * x
Gx, Gy, Gpx, Gpy, Gpt = (G.derivative(v) for v in ("x", "y", "px", "py", "pt"))


def chebyshev(n):
    """T_n(c) and U_{n-1}(c): e^{-in theta} = T_n - i s U_{n-1}."""
    t0, t1 = ctx.from_dict({}) + 1, c
    u0, u1 = ctx.from_dict({}), ctx.from_dict({}) + 1  # U_{-1} = 0, U_0 = 1
    for _ in range(n - 1):
        t0, t1 = t1, 2 * c * t1 - t0
        u0, u1 = u1, 2 * c * u1 - u0
    return t1, u1


def bracket(P0, P1):
    """{P, G} for P = P0(c) + s P1(c), reduced with s^2 = 1 - c^2."""
    # d/dtheta: -s P0_c + c P1 - (1 - c^2) P1_c
    Pth_0 = c * P1 - (1 - c**2) * P1.derivative("c")
    Pth_1 = -P0.derivative("c")
    r0 = P0.derivative("x") * Gpx + P0.derivative("y") * Gpy - P0.derivative("px") * Gx - P0.derivative("py") * Gy + Pth_0 * Gpt
    r1 = P1.derivative("x") * Gpx + P1.derivative("y") * Gpy - P1.derivative("px") * Gx - P1.derivative("py") * Gy + Pth_1 * Gpt
    return r0, r1


def w1(N):
    checked = 0
    terms = 0
    pairs = [(N, N)] if SINGLE else [(m, n) for m in range(1, N + 1) for n in range(1, N + 1)]
    for m, n in pairs:
        if True:
            R, Im = ctx.from_dict({}) + 1, ctx.from_dict({})
            for _ in range(m):
                R, Im = R * A - Im * B, R * B + Im * A
            T, U = chebyshev(n)
            # K = (R + i Im)(T - i s U): P = R T + s Im U, Q = Im T - s R U
            for P0, P1 in ((R * T, Im * U), (Im * T, -(R * U))):
                terms += len(P0) + len(P1)
                r0, r1 = bracket(P0, P1)
                res = flint.fmpq(m, n) * I * w
                r0 = r0.compose(x, y, c, s, px, py, res, M, w, I)
                r1 = r1.compose(x, y, c, s, px, py, res, M, w, I)
                assert r0.is_zero() and r1.is_zero(), (m, n)
                checked += 1
    return checked, terms


t = time.perf_counter()
checked, terms = w1(N)
print(f"checked: {checked}")
print(f"seconds: {time.perf_counter() - t:.3f}")
print(f"terms: {terms}")
