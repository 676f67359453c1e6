#!/usr/bin/env bash
# Regenerates a benchmark section of bench/README.md from one run.
#
#   tools/bench.sh contact [BUILD_DIR]     (BUILD_DIR defaults to build/, configured Release)
#   tools/bench.sh reynolds [BUILD_DIR]
#
# contact: builds bench/contact_bench, runs it on 1 thread (OMP_NUM_THREADS=1) and on 2 threads
# (OMP_NUM_THREADS=2, OMP_WAIT_POLICY=passive: spinning threads are descheduled on a shared
# machine, see bench/README.md), keeps the JSON in out/bench/, and rewrites the block between
# <!-- bench:contact:begin --> and <!-- bench:contact:end --> in bench/README.md with the tables,
# the date and the machine load (uptime before and after, which the tables must be read against).
# Ratios are in process CPU time against an FFTW r2c + c2r pair measured in the same process.
#
# reynolds: builds bench/lubrication_bench and runs the full-film (CHOLMOD, BoomerAMG-PCG, PFMG-PCG) and JFO
# cavitation (UMFPACK, whole-matrix AMG, block-triangular) solves at 128²…1024² (the two slow direct
# paths and whole AMG stop at 512²: 1–2 min each), one process, and rewrites the block between
# <!-- bench:reynolds:begin --> and <!-- bench:reynolds:end --> the same way (≈ 6 min idle).
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-}"
build="${2:-build}"
case "$what" in
  contact | reynolds) ;;
  *) echo "usage: tools/bench.sh contact|reynolds [BUILD_DIR]" >&2; exit 2 ;;
esac

if [ ! -f "$build/CMakeCache.txt" ]; then cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release; fi
mkdir -p out/bench
if [ "$what" = reynolds ]; then
  cmake --build "$build" --target lubrication_bench -j2
  load_before="$(uptime)"
  started="$(date -u '+%Y-%m-%d %H:%M UTC')"
  "$build/bench/lubrication_bench" \
    --benchmark_filter='ReynoldsFullFilm(Multigrid|BoomerAmg)?/(128|256|512|1024)$|ReynoldsCavitation(MultigridWholeAmg)?/(128|256|512)/|ReynoldsCavitationMultigrid(FullFilmStart)?/(128|256|512|1024)/' \
    --benchmark_format=json --benchmark_out=out/bench/reynolds.json --benchmark_out_format=json >/dev/null
  load_after="$(uptime)"
  STARTED="$started" LOAD_BEFORE="$load_before" LOAD_AFTER="$load_after" python3 - <<'EOF'
import json, os, re

scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
rows = {}
for b in json.load(open("out/bench/reynolds.json"))["benchmarks"]:
    m = re.match(r"BM_(\w+?)/(\d+)", b["name"])
    if m and b.get("run_type", "iteration") == "iteration":
        b["cpu_s"] = b["cpu_time"] * scale[b["time_unit"]]
        rows[(m.group(1), int(m.group(2)))] = b

def g(kind, n, key, fmt):
    b = rows.get((kind, n))
    return "—" if b is None or key not in b else fmt.format(b[key])

out = [f"Measured {os.environ['STARTED']} by `tools/bench.sh reynolds`. Machine load — before: "
       f"`{os.environ['LOAD_BEFORE'].strip()}`; after: `{os.environ['LOAD_AFTER'].strip()}`.", "",
       "Full film (pressure only, CPU per solve; PCG stopped at ‖b − Ap‖₂ ≤ 1e-10‖b‖₂):", "",
       "| grid | unknowns | CHOLMOD CPU | BoomerAMG-PCG: CPU, iterations | **PFMG-PCG**: CPU, iterations | PFMG unknowns per CPU s |",
       "|---|---|---|---|---|---|"]
for n in (128, 256, 512, 1024):
    out.append("| {}² | {} | {} s | {} s, {} | **{} s**, {} | {} |".format(
        n, g("ReynoldsFullFilmMultigrid", n, "unknowns", "{:.0f}"), g("ReynoldsFullFilm", n, "cpu_s", "{:.3g}"),
        g("ReynoldsFullFilmBoomerAmg", n, "cpu_s", "{:.3g}"), g("ReynoldsFullFilmBoomerAmg", n, "pcg_iterations", "{:.0f}"),
        g("ReynoldsFullFilmMultigrid", n, "cpu_s", "{:.3g}"), g("ReynoldsFullFilmMultigrid", n, "pcg_iterations", "{:.0f}"),
        g("ReynoldsFullFilmMultigrid", n, "unknowns_per_s", "{:.3g}")))
out += ["", "JFO cavitation (Newton steps on the finest grid; Krylov = all GMRES + PCG iterations; block-triangular "
        "from the full film = without grid sequencing, the disc domain's path):", "",
        "| grid | UMFPACK: CPU, Newton | whole AMG: CPU, Newton, Krylov | block-triangular from the full film: CPU, Newton, Krylov | **block-triangular**: CPU, Newton, Krylov | cavitated fraction |",
        "|---|---|---|---|---|---|"]
for n in (128, 256, 512, 1024):
    cells = []
    for kind, krylov in (("ReynoldsCavitation", False), ("ReynoldsCavitationMultigridWholeAmg", True),
                         ("ReynoldsCavitationMultigridFullFilmStart", True), ("ReynoldsCavitationMultigrid", True)):
        if (kind, n) not in rows:
            cells.append("—")
            continue
        c = g(kind, n, "cpu_s", "{:.3g}") + " s, " + g(kind, n, "newton_iterations", "{:.0f}")
        cells.append(c + (", " + g(kind, n, "pcg_iterations", "{:.0f}") if krylov else ""))
    cells[-1] = "**" + cells[-1] + "**" if cells[-1] != "—" else cells[-1]
    out.append("| {}² | {} | {} | {} | {} | {} |".format(n, *cells, g("ReynoldsCavitationMultigrid", n, "cavitated_fraction", "{:.6f}")))
table = "\n".join(out)
open("out/bench/reynolds.md", "w").write(table + "\n")

readme = open("bench/README.md").read()
begin, end = "<!-- bench:reynolds:begin -->", "<!-- bench:reynolds:end -->"
if begin in readme and end in readme:
    a = readme.index(begin) + len(begin)
    readme = readme[:a] + "\n" + table + "\n" + readme[readme.index(end):]
    open("bench/README.md", "w").write(readme)
    print("bench/README.md: reynolds tables rewritten (copy in out/bench/reynolds.md)")
else:
    print("bench/README.md has no reynolds markers; tables in out/bench/reynolds.md")
EOF
  exit 0
fi

cmake --build "$build" --target contact_bench -j2
load_before="$(uptime)"
started="$(date -u '+%Y-%m-%d %H:%M UTC')"
OMP_NUM_THREADS=1 "$build/bench/contact_bench" --benchmark_filter='threads:1' \
  --benchmark_format=json --benchmark_out=out/bench/contact-t1.json --benchmark_out_format=json >/dev/null
OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive "$build/bench/contact_bench" --benchmark_filter='threads:2' \
  --benchmark_format=json --benchmark_out=out/bench/contact-t2.json --benchmark_out_format=json >/dev/null
load_after="$(uptime)"

STARTED="$started" LOAD_BEFORE="$load_before" LOAD_AFTER="$load_after" python3 - <<'EOF'
import json, os, re

rows = {}
for f in ("out/bench/contact-t1.json", "out/bench/contact-t2.json"):
    for b in json.load(open(f))["benchmarks"]:
        m = re.match(r"BM_(\w+)/n:(\d+)/threads:(\d+)", b["name"])
        if m and b.get("run_type", "iteration") == "iteration":
            rows[(m.group(1), int(m.group(2)), int(m.group(3)))] = b

def g(kind, n, t, key, fmt="{:.2f}"):
    b = rows.get((kind, n, t))
    if b is None or key not in b:
        return "—"
    return fmt.format(b[key])

def ratio(kind, n, t):
    median = g(kind, n, t, "per_iter_over_fft_cpu")
    return "**{}** ({}–{})".format(median, g(kind, n, t, "per_iter_over_fft_cpu_min"), g(kind, n, t, "per_iter_over_fft_cpu_max"))

grids = (256, 512, 1024, 2048)
out = []
out.append(f"Measured {os.environ['STARTED']} by `tools/bench.sh contact`. Machine load — before: "
           f"`{os.environ['LOAD_BEFORE'].strip()}`; after: `{os.environ['LOAD_AFTER'].strip()}`.")
out.append("")
out.append("Per CG iteration, as a multiple of one FFTW r2c + c2r pair on the same grid and thread count "
           "(process CPU time, both measured in the same process: the median of five rounds, each a solve between two "
           "pairs, with the rounds' least and largest ratio in brackets). "
           "Product: the 2-D product with its kernel multiply; line product: the same taken line by line, "
           "as the solve takes it on these periodic grids, with nothing fused into it:")
out.append("")
out.append("| grid | threads | FFT pair CPU | product / pair | line product / pair | update pass / pair | elastic: iterations | pairs / iter | **per iter / pair** | plastic: iterations | pairs / iter | **per iter / pair** |")
out.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
for n in grids:
    for t in (1, 2):
        out.append("| {}² | {} | {} ms | {} | {} | {} | {} | {} | {} | {} | {} | {} |".format(
            n, t, g("ElasticSolve", n, t, "fft_pair_cpu_ms", "{:.3g}"),
            g("Product", n, t, "over_fft_cpu"), g("LineProduct", n, t, "over_fft_cpu"), g("GridPass", n, t, "over_fft_cpu"),
            g("ElasticSolve", n, t, "iterations", "{:.0f}"), g("ElasticSolve", n, t, "pairs_per_iter"),
            ratio("ElasticSolve", n, t),
            g("ElasticPlasticSolve", n, t, "iterations", "{:.0f}"), g("ElasticPlasticSolve", n, t, "pairs_per_iter"),
            ratio("ElasticPlasticSolve", n, t)))
out.append("")
out.append("Whole solves (10 % contact, relative residual 1e-8; medians of the five rounds):")
out.append("")
out.append("| grid | threads | elastic CPU | elastic wall | plastic CPU | plastic wall | peak RSS |")
out.append("|---|---|---|---|---|---|---|")
for n in grids:
    for t in (1, 2):
        out.append("| {}² | {} | {} s | {} s | {} s | {} s | {} MiB |".format(
            n, t, g("ElasticSolve", n, t, "solve_cpu_s", "{:.3g}"), g("ElasticSolve", n, t, "solve_s", "{:.3g}"),
            g("ElasticPlasticSolve", n, t, "solve_cpu_s", "{:.3g}"), g("ElasticPlasticSolve", n, t, "solve_s", "{:.3g}"),
            g("ElasticSolve", n, t, "peak_rss_MiB", "{:.0f}")))
table = "\n".join(out)
open("out/bench/contact.md", "w").write(table + "\n")

readme = open("bench/README.md").read()
begin, end = "<!-- bench:contact:begin -->", "<!-- bench:contact:end -->"
if begin in readme and end in readme:
    a = readme.index(begin) + len(begin)
    b = readme.index(end)
    readme = readme[:a] + "\n" + table + "\n" + readme[b:]
    open("bench/README.md", "w").write(readme)
    print("bench/README.md: contact tables rewritten (copy in out/bench/contact.md)")
else:
    print("bench/README.md has no contact markers; tables in out/bench/contact.md")
EOF
