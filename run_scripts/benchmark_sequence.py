"""Benchmark of the warm-started optimization: every stage's time, iterations and peak memory.

    python run_scripts/benchmark_sequence.py [--output-dir sequence_out] [--no-static-margin]
                                             [--stages rotor_presizing,subproblem_1,...]
                                             [--processes N] [--perturb 0.02 --seed K]

Runs lpc_mdo.warm_start.run_sequence (rotor presizing, subproblems 1-4, the full problem; each
trimmed first and started from the previous stage's final case) in this process, then prints
and writes ``benchmark_sequence.md``: per stage the trim and optimization wall times,
iterations, success and gross mass, the total, the process's peak memory and the last stage's
trim residuals (every Table 6 trim row in % of the weight), next to the
paper's Table 9 (about 30 min for subproblem 1, under 3 min each for 2-4, 63 min for the full
problem after 3.7 h of compilation, on 20 cores).
"""

import argparse
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # see benchmark_lpc.py
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

from lpc_mdo.post.statistics import process_peak_memory_mb  # noqa: E402
from lpc_mdo.post.trim_residuals import trim_residual_table  # noqa: E402
from lpc_mdo.study_plan import SEQUENCE  # noqa: E402
from lpc_mdo.warm_start import perturbed_start_case, run_sequence  # noqa: E402

PAPER_MINUTES = {
    "subproblem_1": 30.0,
    "subproblem_2": 3.0,
    "subproblem_3": 3.0,
    "subproblem_4": 3.0,
    "full": 63.0,
}


def main():
    """Run the warm-start sequence, print the per-stage table and write it to Markdown."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default="sequence_out")
    parser.add_argument("--no-static-margin", action="store_true")
    parser.add_argument("--stages", default=",".join(SEQUENCE))
    parser.add_argument("--start-case", default=None)
    parser.add_argument(
        "--perturb",
        type=float,
        default=0.0,
        help="start from the initial design with every design variable perturbed by up to "
        "this fraction (uniform, clipped to the bounds), e.g. 0.02",
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of --perturb")
    parser.add_argument("--max-iter", type=int, default=400)
    parser.add_argument(
        "--processes", type=int, default=os.cpu_count() or 1, help="trim processes per stage"
    )
    args = parser.parse_args()

    start_case = args.start_case
    if args.perturb:
        if start_case is not None:
            parser.error("--perturb and --start-case exclude each other")
        os.makedirs(args.output_dir, exist_ok=True)
        start_case = perturbed_start_case(
            os.path.join(args.output_dir, "perturbed_start.sql"), args.perturb, args.seed
        )
    start = time.perf_counter()
    results = run_sequence(
        args.output_dir,
        names=args.stages.split(","),
        static_margin=not args.no_static_margin,
        start_case=start_case,
        driver_settings={"max_iter": args.max_iter, "print_level": 0},
        trim_processes=args.processes,
    )
    total = time.perf_counter() - start
    lines = [
        "| stage | trim (s) | optimization (s) | iterations | success | gross mass (kg) | "
        "paper (min, 20 cores) |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in results:
        paper = PAPER_MINUTES.get(r.name)
        lines.append(
            f"| {r.name} | {r.trim_seconds:.1f} | {r.seconds:.1f} | {r.iterations} | "
            f"{r.success} | {r.gross_mass:.2f} | {'' if paper is None else paper} |"
        )
    lines.append(
        f"\nTotal wall time {total:.1f} s ({total / 60:.1f} min); peak memory "
        f"{process_peak_memory_mb():.0f} MB; static margin "
        f"{'off' if args.no_static_margin else 'on'}."
    )
    # Every Table 6 trim row of the last stage, declared or not, as force/moment in % of W0.
    lines.append("\n" + trim_residual_table(results[-1].case_file).to_markdown())
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(args.output_dir, "benchmark_sequence.md"), "w", encoding="utf-8") as fh:
        fh.write(text + "\n")
    failed = [r.name for r in results if not r.success]
    if failed:
        # A stage that did not converge fails the benchmark, not only its table row.
        print(f"FAILED: {', '.join(failed)} did not converge", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
