"""Runs superint and its peers on the workloads W1-W4, alternating, and prints medians and ratios.

    python compare.py [--repeats 3] [--quick] [--markdown]
    python compare.py --sympy-goal [--repeats 3] [--max-cap 1800] [--markdown]

Each (workload, size) row is run by every tool in turn, `--repeats` times; the table shows the
median seconds of each tool and the ratio superint / peer (below 1: superint is faster). Every
run must report the expected number of exact zeros (the identities hold), and the products of W3
the same number of terms as superint, or the script stops. (The terms of P and Q in W1, W2 differ
between tools by design: superint stores angles as e^{ikθ}, the peers as cos θ, sin θ.) Peak memory (max RSS) of W1 is measured in a separate
run per tool. SymPy runs at smaller sizes, where it finishes in seconds; superint runs those
sizes too, so each ratio compares equal work.

`--sympy-goal` measures the goal of issue 5 (superint at least 300x faster than SymPy) at the
workloads' defined sizes (GOAL below). Per row: superint and python-flint `--repeats` times,
alternating (medians), then SymPy once, stopped at a cap of 300 x superint's median (and at most
`--max-cap` seconds). The cap is on SymPy's own timing; the subprocess timeout adds SymPy's
start-up (interpreter and import, measured once), so a stopped run had spent at least the cap
in the workload. A finished SymPy run is checked like the normal mode and gives the ratios
superint / SymPy and python-flint / SymPy; a stopped run gives `> CAP s` and upper bounds on
the ratios (< superint / CAP), which prove the goal when CAP is the full 300 x superint.

SymPy's speed depends on its ground types (the integers and rationals under its polynomials):
python-flint's, gmpy2's, or pure Python's. `--sympy-ground` (default `flint,gmpy`) names the
ones to run; SymPy runs under each, alternating with the other tools, and its column is the
fastest of them, marked with its ground types, so that every ratio is against SymPy at its best.
Each SymPy run reports the ground types in use, and the script stops if they are not the ones
asked for (SymPy falls back to pure Python when a library is missing).

The binary is `SUPERINT_BIN` (target/release/superint by default), and `SUPERINT_BUILD` says
how it was built; both are printed under each table (run.sh --pgo sets them).
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SUPERINT = os.environ.get("SUPERINT_BIN", os.path.join(ROOT, "target", "release", "superint"))
# How the binary was built, printed under each table (run.sh --pgo sets it).
BUILD = os.environ.get("SUPERINT_BUILD", "cargo build --release")
PYTHON = os.environ.get("PEERS_PYTHON", sys.executable)

NAMES = {"tower": "W1 tower", "single": "W2 single", "fateman": "W3a Fateman",
         "pearce": "W3b Pearce", "algebra": "W4 algebra"}
# (workload, size, tools)
FULL = [("tower", 24, "superint superint2 flint singular"),
        ("single", 80, "superint superint2 flint singular"),
        ("fateman", 20, "superint superint2 flint singular"),
        ("pearce", 12, "superint superint2 flint singular"),
        ("algebra", 1000, "superint superint2 flint singular"),
        ("tower", 8, "superint sympy"), ("single", 20, "superint sympy"),
        ("fateman", 10, "superint sympy"), ("pearce", 4, "superint sympy"),
        ("algebra", 100, "superint sympy")]
QUICK = [("tower", 8, "superint superint2 flint singular sympy"),
         ("single", 20, "superint superint2 flint singular sympy"),
         ("fateman", 10, "superint superint2 flint singular sympy"),
         ("pearce", 4, "superint superint2 flint singular sympy"),
         ("algebra", 100, "superint superint2 flint singular sympy")]
# the goal rows: every workload at its defined sizes
GOAL = [("tower", 8), ("tower", 16), ("tower", 24), ("single", 40), ("single", 80),
        ("fateman", 20), ("pearce", 12), ("algebra", 1000)]
GOAL_FACTOR = 300  # superint at least this many times faster than SymPy
EXPECTED_ZEROS = {"tower": lambda n: 2 * n * n, "single": lambda n: 2, "fateman": lambda n: 0,
                  "pearce": lambda n: 0, "algebra": lambda n: n}


def sympy_ground(tool):
    """The ground types of a SymPy tool (`sympy:flint`), or None for any other tool."""
    name, _, ground = tool.partition(":")
    return ground if name == "sympy" else None


def command(tool, workload, size):
    """The command line of one run, its standard input and its environment."""
    if tool == "superint":
        return [SUPERINT, "bench", workload, str(size)], None, None
    if tool == "superint2":  # on two threads (W1 pairs, W2 brackets, W3 product parts, W4 repetitions)
        return [SUPERINT, "bench", workload, str(size), "--threads", "2"], None, None
    if tool == "flint":
        return [PYTHON, os.path.join(HERE, "peers.py"), tool, workload, str(size)], None, None
    if sympy_ground(tool):
        env = dict(os.environ, SYMPY_GROUND_TYPES=sympy_ground(tool))
        return [PYTHON, os.path.join(HERE, "peers.py"), "sympy", workload, str(size)], None, env
    if tool == "singular":
        with open(os.path.join(HERE, "workloads.sing")) as f:
            script = f'string W = "{workload}"; int N = {size};\n' + f.read()
        return ["Singular", "-q", "--no-warn"], script, None
    raise ValueError(tool)


def run(tool, workload, size, timeout=None):
    """Runs once; returns (seconds, terms, zeros) as the tool reports them. Past `timeout`
    seconds the process is killed and subprocess.TimeoutExpired raised."""
    cmd, stdin, env = command(tool, workload, size)
    out = subprocess.run(cmd, input=stdin, capture_output=True, text=True, check=True,
                         timeout=timeout, env=env).stdout
    fields = dict(re.findall(r"^(\w+): (\S+)$", out, re.M))
    ground = sympy_ground(tool)
    if ground and fields.get("ground") != ground:
        sys.exit(f"{tool}: SymPy ran on {fields.get('ground')} ground types, not {ground} "
                 f"(is its library installed?)")
    seconds = float(fields["seconds"]) if "seconds" in fields else int(fields["ms"]) / 1000
    return seconds, int(fields["terms"]), int(fields["zeros"])


def check(tool, workload, size, terms, zeros, reference):
    """Stops the script unless the run found the expected exact zeros and, for the products of
    W3, the same number of terms as `reference` (superint's)."""
    want = EXPECTED_ZEROS[workload](size)
    if zeros != want:
        sys.exit(f"{tool} {workload} {size}: {zeros} exact zeros, expected {want}")
    if reference is not None and workload in ("fateman", "pearce") and terms != reference:
        sys.exit(f"{tool} {workload} {size}: {terms} terms, superint had {reference}")


def alternate(tools, workload, size, repeats):
    """Runs every tool `repeats` times, alternating within each repeat, checking each run;
    returns the median seconds per tool and the first tool's term count."""
    times = {t: [] for t in tools}
    reference = None
    for _ in range(repeats):
        for tool in tools:
            seconds, terms, zeros = run(tool, workload, size)
            check(tool, workload, size, terms, zeros, reference)
            if reference is None:
                reference = terms
            times[tool].append(seconds)
    return {t: statistics.median(v) for t, v in times.items()}, reference


def peak_memory_kib(tool, workload, size):
    """Max RSS of one run, measured in a fresh wrapper process so earlier runs do not count."""
    cmd, stdin, env = command(tool, workload, size)
    probe = ("import resource, subprocess, sys; "
             "subprocess.run(sys.argv[2:], input=sys.argv[1] or None, text=True, capture_output=True, check=True); "
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    out = subprocess.run([sys.executable, "-c", probe, stdin or ""] + cmd,
                         capture_output=True, text=True, check=True, env=env).stdout
    return int(out.strip())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="small sizes only (for CI)")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--no-memory", action="store_true")
    ap.add_argument("--sympy-goal", action="store_true",
                    help="SymPy at the goal sizes, capped at 300 x superint's time")
    ap.add_argument("--max-cap", type=float, default=1800,
                    help="with --sympy-goal: stop any one SymPy run after this many seconds")
    ap.add_argument("--sympy-ground", default="flint,gmpy",
                    help="SymPy's ground types to run, comma-separated (flint, gmpy, python); "
                         "its figure is the fastest")
    ap.add_argument("--rows", help=argparse.SUPPRESS)  # testing: e.g. tower:8,algebra:100
    args = ap.parse_args()
    args.sympy_tools = [f"sympy:{g}" for g in args.sympy_ground.split(",")]
    if args.sympy_goal:
        plan = GOAL
        if args.rows:
            plan = [(w, int(n)) for w, n in (r.split(":") for r in args.rows.split(","))]
        return sympy_goal(plan, args)
    plan = QUICK if args.quick else FULL
    rows = []
    for workload, size, tools in plan:
        tools = [s for t in tools.split() for s in (args.sympy_tools if t == "sympy" else [t])]
        medians, reference = alternate(tools, workload, size, args.repeats)
        rows.append((workload, size, medians, reference))
        print(f"  {NAMES[workload]} {size}: " + ", ".join(f"{t} {m:.4f} s" for t, m in medians.items()),
              file=sys.stderr, flush=True)
    memory = {}
    if not args.no_memory:
        w, n = ("tower", 8) if args.quick else ("tower", 24)
        for tool in ("superint", "flint", "singular"):
            memory[tool] = peak_memory_kib(tool, w, n)
    print_table(rows, memory, args.markdown, args.repeats, args.sympy_tools)


def fastest_sympy(times):
    """SymPy's fastest figure among its ground types in `times` (tool: seconds, None for a run
    stopped at its cap), as (seconds, ground types); None when there is none."""
    finished = [(t, sympy_ground(tool)) for tool, t in times.items()
                if sympy_ground(tool) and t is not None]
    return min(finished) if finished else None


def print_rows(head, lines, markdown):
    """A table with a header row, as markdown or as right-aligned text columns."""
    if markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for c in lines:
            print("| " + " | ".join(c) + " |")
    else:
        widths = [max(len(r[k]) for r in [head] + lines) for k in range(len(head))]
        for r in [head] + lines:
            print("  ".join(c.rjust(w) for c, w in zip(r, widths)))


def print_table(rows, memory, markdown, repeats, sympy_tools):
    peers = ["flint", "singular", "sympy"]
    label = {"flint": "python-flint", "singular": "Singular", "sympy": "SymPy"}
    head = ["workload", "size", "superint terms", "superint s", "superint 2 threads s"]
    for p in peers:
        head += [f"{label[p]} s", f"ratio vs {label[p]}"]
    lines = []
    for workload, size, med, terms in rows:
        two = f"{med['superint2']:.4f}" if "superint2" in med else ""
        cells = [NAMES[workload], str(size), str(terms), f"{med['superint']:.4f}", two]
        for p in peers:
            if p == "sympy" and (best := fastest_sympy(med)):
                seconds, ground = best
                cells += [f"{seconds:.4f} ({ground})", f"{med['superint'] / seconds:.3g}"]
            elif p in med:
                cells += [f"{med[p]:.4f}", f"{med['superint'] / med[p]:.3g}"]
            else:
                cells += ["", ""]
        lines.append(cells)
    print_rows(head, lines, markdown)
    print(f"\nmedian of {repeats} runs per tool, tools alternating; ratio = single-threaded "
          "superint / peer (below 1: superint is faster); superint's 2-thread column is "
          "`--threads 2`, pinned one to a processor; every run reported the identities as "
          "exact zeros.")
    print(f"superint: {SUPERINT} ({BUILD}); SymPy: the fastest of its ground types "
          f"{', '.join(sympy_ground(t) for t in sympy_tools)} (each in parentheses)")
    if memory:
        print("peak memory (max RSS) of W1: " + ", ".join(
            f"{label.get(t, t)} {kib / 1024:.1f} MiB" for t, kib in memory.items()))


def sympy_startup(tool):
    """Wall seconds of SymPy's start-up alone (interpreter, import, ring), median of three."""
    walls = []
    for _ in range(3):
        start = time.perf_counter()
        run(tool, "algebra", 0)
        walls.append(time.perf_counter() - start)
    return statistics.median(walls)


def sympy_goal(plan, args):
    startup = {tool: sympy_startup(tool) for tool in args.sympy_tools}
    print("  SymPy start-up " + ", ".join(f"{sympy_ground(t)} {s:.2f} s" for t, s in startup.items())
          + ", added to each timeout", file=sys.stderr, flush=True)
    rows = []
    for workload, size in plan:
        med, reference = alternate(["superint", "superint2", "flint"], workload, size,
                                   args.repeats)
        cap = min(GOAL_FACTOR * med["superint"], args.max_cap)
        print(f"  {NAMES[workload]} {size}: superint {med['superint']:.4f} s, flint "
              f"{med['flint']:.4f} s; SymPy capped at {cap:.1f} s ...", file=sys.stderr, flush=True)
        for tool in args.sympy_tools:
            try:
                seconds, terms, zeros = run(tool, workload, size, timeout=cap + startup[tool])
                check(tool, workload, size, terms, zeros, reference)
                med[tool] = seconds
            except subprocess.TimeoutExpired:
                med[tool] = None
            print(f"  {NAMES[workload]} {size}: SymPy ({sympy_ground(tool)}) "
                  + (f"{med[tool]:.4f} s" if med[tool] is not None else "stopped at the cap"),
                  file=sys.stderr, flush=True)
        rows.append((workload, size, med, cap, reference))
    print_goal_table(rows, args)


def one_over(x):
    """A ratio below 1 as 1/N (N to three digits, or whole from 100 on)."""
    if x >= 1:
        return f"{x:.3g}"
    n = 1 / x
    return f"1/{n:.0f}" if n >= 100 else f"1/{n:.3g}"


def print_goal_table(rows, args):
    markdown, repeats, max_cap = args.markdown, args.repeats, args.max_cap
    head = ["workload", "size", "superint terms", "superint s", "superint 2 threads s",
            "python-flint s", "SymPy cap s", "SymPy s", "superint / SymPy",
            "superint 2 threads / SymPy", "python-flint / SymPy", f"goal {GOAL_FACTOR}x",
            f"goal {GOAL_FACTOR}x, 2 threads"]
    lines = []
    for workload, size, med, cap, terms in rows:
        si, si2, fl = med["superint"], med["superint2"], med["flint"]
        cells = [NAMES[workload], str(size), str(terms), f"{si:.4f}", f"{si2:.4f}", f"{fl:.4f}",
                 f"{cap:.1f}"]
        if best := fastest_sympy(med):
            sy, ground = best
            cells += [f"{sy:.4f} ({ground})", one_over(si / sy), one_over(si2 / sy), one_over(fl / sy),
                      "yes" if sy >= GOAL_FACTOR * si else "no",
                      "yes" if sy >= GOAL_FACTOR * si2 else "no"]
        else:  # stopped at the cap: SymPy > cap, so the ratios are upper bounds
            def bound(t):
                return "yes (bound)" if cap >= GOAL_FACTOR * t else "open (max cap)"
            cells += [f"> {cap:.1f}", "< " + one_over(si / cap), "< " + one_over(si2 / cap),
                      "< " + one_over(fl / cap), bound(si), bound(si2)]
        lines.append(cells)
    print_rows(head, lines, markdown)
    print(f"\nsuperint (on one thread, and with `--threads 2`, pinned one to a processor) and "
          f"python-flint: median of {repeats} runs, alternating; "
          f"SymPy: one run on each of its ground types "
          f"{', '.join(sympy_ground(t) for t in args.sympy_tools)}, the fastest shown (its ground "
          f"types in parentheses), each stopped at the cap = {GOAL_FACTOR} x superint's one-thread median (at most "
          f"{max_cap:g} s); ratio = tool / SymPy, goal superint / SymPy <= 1/{GOAL_FACTOR}. "
          f"`> CAP`: SymPy did not finish within the cap, so the ratios are upper bounds "
          f"(< tool / CAP); at the full {GOAL_FACTOR}x cap that proves the goal (yes (bound)), "
          f"at the max cap it may not (open). Every finished run reported the identities as exact "
          f"zeros.")
    print(f"superint: {SUPERINT} ({BUILD})")


if __name__ == "__main__":
    main()
