#!/usr/bin/env bash
# A profile-guided build of the command-line program: target/pgo/release/superint.
#   scripts/pgo.sh            # prints the binary's path as its last line
#
# Three steps, as rustc's book describes them (the profile-guided optimisation chapter), and a
# check:
#   1. build an instrumented binary (`-Cprofile-generate`) in target/pgo/generate;
#   2. run it on the training work below, which writes raw profiles;
#   3. merge them with the toolchain's own llvm-profdata (rustup's `llvm-tools`, installed here
#      when missing: its profile format must be the compiler's LLVM's) and build again with
#      `-Cprofile-use`, so that the compiler lays out and inlines the code by how often it ran;
#   4. the optimised binary must print what the instrumented one prints for the paper's claims
#      and every system file, or the script fails.
#
# The training is the program's own work: the default job (the paper's claims), every system
# file, a search and a closure, and each benchmark workload at a size far below the measured
# one, the size SymPy runs it at in the comparison (Pearce's at 8, so that the two-thread
# pipeline of large products runs). A profile holds how often each branch and call ran, not
# results: the binary computes the same as `cargo build --release`'s, and the comparison checks
# every identity it reports (docs/performance.md, "Profile-guided build").
#
# The flags go through `--config` on the host's target table, so they join the workspace's own
# (.cargo/config.toml) instead of replacing them, as RUSTFLAGS would.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

host="$(rustc -vV | sed -n 's/^host: //p')"
sysroot="$(rustc --print sysroot)"
profdata="$sysroot/lib/rustlib/$host/bin/llvm-profdata"
if [ ! -x "$profdata" ]; then
  echo "installing rustup's llvm-tools (llvm-profdata for this compiler's LLVM)" >&2
  rustup component add llvm-tools >&2
fi

out="$root/target/pgo"
raw="$out/raw"
merged="$out/merged.profdata"
rm -rf "$raw" "$merged"
mkdir -p "$raw"

build() { # target-dir, rustflag
  cargo build --release --quiet --target-dir "$1" \
    --config "target.$host.rustflags=[\"$2\"]"
}

echo "1/4 instrumented build" >&2
build "$out/generate" "-Cprofile-generate=$raw"
train="$out/generate/release/superint"

echo "2/4 training" >&2
"$train" >/dev/null
"$train" check systems/*.toml >/dev/null
"$train" search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
  --momenta-degree 3 --positions-degree 3 --trig-degree 3 >/dev/null
"$train" closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_1 Q_1_1 \
  --when 'p_theta = I*omega' --degree 2 >/dev/null
for threads in 1 2; do
  "$train" bench --threads "$threads" W1 8 >/dev/null
  "$train" bench --threads "$threads" W2 20 >/dev/null
  "$train" bench --threads "$threads" W3a 10 >/dev/null
  "$train" bench --threads "$threads" W3b 8 >/dev/null
  "$train" bench --threads "$threads" W4 100 >/dev/null
done

echo "3/4 optimised build" >&2
"$profdata" merge -o "$merged" "$raw"
build "$out" "-Cprofile-use=$merged"
optimised="$out/release/superint"

# The same sources: the optimised binary must print what the instrumented one prints.
echo "4/4 the paper's claims and the system files, against the instrumented build" >&2
same() {
  if ! cmp -s <("$train" "$@" --no-timings) <("$optimised" "$@" --no-timings); then
    echo "pgo.sh: the profile-guided build prints otherwise: superint $*" >&2
    exit 1
  fi
}
same
same check systems/*.toml
echo "$optimised"
