"""The workloads W1-W4 (see src/workloads.rs) in python-flint and SymPy, one formulation for both.

    python peers.py flint W1 24
    python peers.py sympy W3a 10

Prints `zeros: K` (identities found exactly zero), `seconds: X` and `terms: T`, like
`superint bench`. The formulation is the paper's normal form: cos θ, sin θ as variables c, s
with s² = 1 − c² applied by hand; complex numbers as pairs of real polynomials; 1/M and 1/I
removed by scaling H by the constant 2MI (which does not change whether a bracket vanishes).

SymPy runs through its sparse polynomial ring (sympy.polys.rings), the fastest SymPy
polynomial type we measured (faster than the Poly class, which wraps dense recursive DMP), on
the ground types that SYMPY_GROUND_TYPES selects (flint, gmpy or python; SymPy's own default
takes python-flint when it is installed, as it is beside this script): SymPy prints them as
`ground: G`, so that a caller can tell that the ones it asked for are the ones in use.
"""
import sys
import time
from fractions import Fraction

BACKEND, WORKLOAD, SIZE = sys.argv[1], sys.argv[2].lower(), int(sys.argv[3])

if BACKEND == "flint":
    import flint

    def make_ring(names):
        ctx = flint.fmpq_mpoly_ctx.get(tuple(names), "lex")
        gens = ctx.gens()
        one = ctx.from_dict({}) + 1
        names = list(names)

        def diff(f, v):
            return f.derivative(names.index(v))

        def subst(f, v, value):
            args = [value if n == v else g for n, g in zip(names, gens)]
            return f.compose(*args)

        def rational(p, q):
            return flint.fmpq(p, q) * one

        return gens, one, diff, subst, rational

elif BACKEND == "sympy":
    from sympy import QQ
    from sympy.external.gmpy import GROUND_TYPES
    from sympy.polys.rings import ring

    def make_ring(names):
        R, *gens = ring(",".join(names), QQ)
        index = {n: k for k, n in enumerate(names)}

        def diff(f, v):
            return f.diff(gens[index[v]])

        def subst(f, v, value):
            return f.compose(gens[index[v]], value)

        def rational(p, q):
            return R(QQ(p, q))

        return gens, R(1), diff, subst, rational

else:
    sys.exit(f"unknown backend {BACKEND}")


def tower(pairs):
    """W1/W2: {P, 2MI·H} and {Q, 2MI·H} at p_theta = m I omega / n, for each (m, n)."""
    names = ("x", "y", "c", "s", "px", "py", "pt", "M", "w", "I")
    (x, y, c, s, px, py, pt, M, w, I), one, diff, subst, rational = make_ring(names)
    G = I * (px**2 + py**2) + M**2 * w**2 * I * (x**2 + y**2) + M * pt**2  # 2MI·H
    A = px - M * w * y  # Z = A + iB
    B = py + M * w * x
    dG = {v: diff(G, v) for v in ("x", "y", "px", "py", "pt")}

    def bracket_part(f):
        return (diff(f, "x") * dG["px"] + diff(f, "y") * dG["py"]
                - diff(f, "px") * dG["x"] - diff(f, "py") * dG["y"])

    zeros = terms = 0
    for m, n in pairs:
        R, Im = one, 0 * one
        for _ in range(m):  # (R + i Im) = Z^m
            R, Im = R * A - Im * B, R * B + Im * A
        T, U, T0, U0 = c, one, one, 0 * one  # e^{-in theta} = T_n(c) - i s U_{n-1}(c)
        for _ in range(n - 1):
            T, T0 = 2 * c * T - T0, T
            U, U0 = 2 * c * U - U0, U
        # K = (R + i Im)(T - i s U): P = R T + s Im U, Q = Im T - s R U
        for P0, P1 in ((R * T, Im * U), (Im * T, -(R * U))):
            terms += len(P0) + len(P1)
            # d/dtheta (P0 + s P1) = (c P1 - (1 - c^2) P1_c) - s P0_c
            r0 = bracket_part(P0) + (c * P1 - (1 - c**2) * diff(P1, "c")) * dG["pt"]
            r1 = bracket_part(P1) - diff(P0, "c") * dG["pt"]
            value = rational(m, n) * I * w
            if subst(r0, "pt", value) == 0 and subst(r1, "pt", value) == 0:
                zeros += 1
    return zeros, terms


def products(which, n):
    (x, y, z, t, u), one, _, _, _ = make_ring(("x", "y", "z", "t", "u"))
    if which == "fateman":
        f = (1 + x + y + z + t) ** n
        r = f * (f + 1)
    else:
        f = (1 + x + y + 2 * z**2 + 3 * t**3 + 5 * u**5) ** n
        g = (1 + u + t + 2 * z**2 + 3 * y**3 + 5 * x**5) ** n
        r = f * g
    return 0, len(r)


def algebra(reps):
    """W4: the su(2) brackets and the Casimir, scaled by 2M: g1 = 2M G1, g2 = 2M G2."""
    names = ("x", "y", "px", "py", "M", "w")
    (x, y, px, py, M, w), one, diff, _, _ = make_ring(names)

    def bracket(f, g):
        return (diff(f, "x") * diff(g, "px") - diff(f, "px") * diff(g, "x")
                + diff(f, "y") * diff(g, "py") - diff(f, "py") * diff(g, "y"))

    # The generators are the inputs, built once (superint takes them from its system); the
    # brackets and every square, h^2 included, are computed in every repetition.
    mw2 = M**2 * w**2
    L = x * py - y * px
    g1 = px * py + mw2 * x * y
    g2 = px**2 - py**2 + mw2 * (x**2 - y**2)
    h = px**2 + py**2 + mw2 * (x**2 + y**2)  # 2M (F1 - F2)
    zeros = terms = 0
    for _ in range(reps):
        b1, b2, b3 = bracket(L, g1), bracket(L, g2), bracket(g1, g2)
        checks = [
            b1 + g2,  # {L, G1} = -G2
            b2 - 4 * g1,  # {L, G2} = 4 G1
            b3 + 4 * mw2 * L,  # {G1, G2} = -w^2 L, times (2M)^2
            4 * g1**2 + g2**2 + 4 * mw2 * L**2 - h**2,  # the Casimir, times (2M)^2
        ]
        terms += len(b1) + len(b2) + len(b3)
        zeros += all(e == 0 for e in checks)
    return zeros, terms


start = time.perf_counter()
if WORKLOAD in ("w1", "tower"):
    zeros, terms = tower([(m, n) for m in range(1, SIZE + 1) for n in range(1, SIZE + 1)])
elif WORKLOAD in ("w2", "single"):
    zeros, terms = tower([(SIZE, SIZE)])
elif WORKLOAD in ("w3", "w3a", "fateman"):
    zeros, terms = products("fateman", SIZE)
elif WORKLOAD in ("w3b", "pearce"):
    zeros, terms = products("pearce", SIZE)
elif WORKLOAD in ("w4", "algebra"):
    zeros, terms = algebra(SIZE)
else:
    sys.exit(f"unknown workload {WORKLOAD}")
if BACKEND == "sympy":
    print(f"ground: {GROUND_TYPES}")
print(f"zeros: {zeros}")
print(f"seconds: {time.perf_counter() - start:.6f}")
print(f"terms: {terms}")
