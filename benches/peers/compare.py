"""Runs superint and its peers on the workloads W1-W4, alternating, and prints medians and ratios.

    python compare.py [--repeats 3] [--quick] [--markdown]

Each (workload, size) row is run by every tool in turn, `--repeats` times; the table shows the
median seconds of each tool and the ratio superint / peer (below 1: superint is faster). Every
run must report the expected number of exact zeros (the identities hold), and the products of W3
the same number of terms as superint, or the script stops. (The terms of P and Q in W1, W2 differ
between tools by design: superint stores angles as e^{ikθ}, the peers as cos θ, sin θ.) Peak memory (max RSS) of W1 is measured in a separate
run per tool. SymPy runs at smaller sizes, where it finishes in seconds; superint runs those
sizes too, so each ratio compares equal work.
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
PYTHON = os.environ.get("PEERS_PYTHON", sys.executable)

NAMES = {"tower": "W1 tower", "single": "W2 single", "fateman": "W3a Fateman",
         "pearce": "W3b Pearce", "algebra": "W4 algebra"}
# (workload, size, tools)
FULL = [("tower", 24, "superint superint2 flint singular"),
        ("single", 80, "superint superint2 flint singular"),
        ("fateman", 20, "superint flint singular"), ("pearce", 12, "superint flint singular"),
        ("algebra", 1000, "superint flint singular"),
        ("tower", 8, "superint sympy"), ("single", 20, "superint sympy"),
        ("fateman", 10, "superint sympy"), ("pearce", 4, "superint sympy"),
        ("algebra", 100, "superint sympy")]
QUICK = [("tower", 8, "superint superint2 flint singular sympy"),
         ("single", 20, "superint superint2 flint singular sympy"),
         ("fateman", 10, "superint flint singular sympy"), ("pearce", 4, "superint flint singular sympy"),
         ("algebra", 100, "superint flint singular sympy")]
EXPECTED_ZEROS = {"tower": lambda n: 2 * n * n, "single": lambda n: 2, "fateman": lambda n: 0,
                  "pearce": lambda n: 0, "algebra": lambda n: n}


def command(tool, workload, size):
    if tool == "superint":
        return [SUPERINT, "bench", workload, str(size)], None
    if tool == "superint2":  # the same on two threads (W1 pairs and W2 brackets in parallel)
        return [SUPERINT, "bench", workload, str(size), "--threads", "2"], None
    if tool in ("flint", "sympy"):
        return [PYTHON, os.path.join(HERE, "peers.py"), tool, workload, str(size)], None
    if tool == "singular":
        with open(os.path.join(HERE, "workloads.sing")) as f:
            script = f'string W = "{workload}"; int N = {size};\n' + f.read()
        return ["Singular", "-q", "--no-warn"], script
    raise ValueError(tool)


def run(tool, workload, size):
    """Runs once; returns (seconds, terms, zeros) as the tool reports them."""
    cmd, stdin = command(tool, workload, size)
    out = subprocess.run(cmd, input=stdin, capture_output=True, text=True, check=True).stdout
    fields = dict(re.findall(r"^(\w+): (\S+)$", out, re.M))
    seconds = float(fields["seconds"]) if "seconds" in fields else int(fields["ms"]) / 1000
    return seconds, int(fields["terms"]), int(fields["zeros"])


def peak_memory_kib(tool, workload, size):
    """Max RSS of one run, measured in a fresh wrapper process so earlier runs do not count."""
    cmd, stdin = command(tool, workload, size)
    probe = ("import resource, subprocess, sys; "
             "subprocess.run(sys.argv[2:], input=sys.argv[1] or None, text=True, capture_output=True, check=True); "
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    out = subprocess.run([sys.executable, "-c", probe, stdin or ""] + cmd,
                         capture_output=True, text=True, check=True).stdout
    return int(out.strip())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="small sizes only (for CI)")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--no-memory", action="store_true")
    args = ap.parse_args()
    plan = QUICK if args.quick else FULL
    rows = []
    for workload, size, tools in plan:
        tools = tools.split()
        times = {t: [] for t in tools}
        reference = None
        for _ in range(args.repeats):
            for tool in tools:  # alternate the tools within each repeat
                seconds, terms, zeros = run(tool, workload, size)
                want = EXPECTED_ZEROS[workload](size)
                if zeros != want:
                    sys.exit(f"{tool} {workload} {size}: {zeros} exact zeros, expected {want}")
                if reference is None:
                    reference = terms
                elif workload in ("fateman", "pearce") and terms != reference:
                    sys.exit(f"{tool} {workload} {size}: {terms} terms, superint had {reference}")
                times[tool].append(seconds)
        medians = {t: statistics.median(v) for t, v in times.items()}
        rows.append((workload, size, medians, reference))
        print(f"  {NAMES[workload]} {size}: " + ", ".join(f"{t} {m:.4f} s" for t, m in medians.items()),
              file=sys.stderr, flush=True)
    memory = {}
    if not args.no_memory:
        w, n = ("tower", 8) if args.quick else ("tower", 24)
        for tool in ("superint", "flint", "singular"):
            memory[tool] = peak_memory_kib(tool, w, n)
    print_table(rows, memory, args.markdown, args.repeats)


def print_table(rows, memory, markdown, repeats):
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
            if p in med:
                cells += [f"{med[p]:.4f}", f"{med['superint'] / med[p]:.3g}"]
            else:
                cells += ["", ""]
        lines.append(cells)
    if markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for c in lines:
            print("| " + " | ".join(c) + " |")
    else:
        widths = [max(len(r[k]) for r in [head] + lines) for k in range(len(head))]
        for r in [head] + lines:
            print("  ".join(c.rjust(w) for c, w in zip(r, widths)))
    print(f"\nmedian of {repeats} runs per tool, tools alternating; ratio = single-threaded "
          "superint / peer (below 1: superint is faster); every run reported the identities as "
          "exact zeros.")
    if memory:
        print("peak memory (max RSS) of W1: " + ", ".join(
            f"{label.get(t, t)} {kib / 1024:.1f} MiB" for t, kib in memory.items()))


if __name__ == "__main__":
    main()
