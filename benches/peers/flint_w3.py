"""W3 products with python-flint (fmpq_mpoly): Fateman f·(f+1), f = (1+x+y+z+t)^20, and the
sparse Pearce product (1+x+y+2z²+3t³+5u⁵)^12 · (1+u+t+2z²+3y³+5x⁵)^12."""
import sys
import time

import flint

which = sys.argv[1] if len(sys.argv) > 1 else "fateman"
size = int(sys.argv[2]) if len(sys.argv) > 2 else (20 if which == "fateman" else 12)
ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "z", "t", "u"), "lex")
x, y, z, t, u = ctx.gens()
t0 = time.perf_counter()
if which == "fateman":
    f = (1 + x + y + z + t) ** size
    r = f * (f + 1)
else:
    f = (1 + x + y + 2 * z**2 + 3 * t**3 + 5 * u**5) ** size
    g = (1 + u + t + 2 * z**2 + 3 * y**3 + 5 * x**5) ** size
    r = f * g
print(f"seconds: {time.perf_counter() - t0:.3f}")
print(f"terms: {len(r)}")
