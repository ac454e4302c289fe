#!/usr/bin/python3
"""Writes BENCHMARKS.md and its SVG plots from the raw benchmark output.

Input (written by bench/benchmarks.sh under out/benchmarks/):
  morph.jsonl         stickmorph_benchmark_morph --json: one object per (case, method)
  polygon_pairs.json  stickmorph_benchmark --json: the polygon-pair corpus
  run.json            machine, date, commit, command and runtime of the run
  motion.json         bench/motion_quality.py --json on the motion corpus
                      (optional: without it the report says that motion
                      quality was not measured)
  correspondence.json stickmorph_benchmark_correspondence --json: automatic
                      correspondence against size (optional, likewise)
  scrub.jsonl         stickmorph_benchmark_scrub --json: frames per second of
                      the stateful solvers (issue 15; optional, likewise)
  blender.json        bench/blender_bake.py --json: the bake and playback in
                      headless Blender (issue 29; optional, likewise)
  local_timing.json   bench/local_timing.py --json: the measured lag of a delayed
                      limb against the overlap asked (issue 31; optional, likewise)
  cleaning.json       bench/cleaning.py --json: `stickmorph clean` on hand-drawn-like
                      drawings (issue 32; optional, likewise)

Output: BENCHMARKS.md and docs/benchmarks/*.svg. Every number in them comes
from the input files; the text around them only explains. Runs with Debian's
/usr/bin/python3; the plots are drawn with matplotlib (Debian
python3-matplotlib).
"""

import argparse
import os
import sys

# The report's sections live in bench/benchmarks_md/, one module each (its __init__.py lists them);
# the names below are re-exported for tests/python/test_make_benchmarks_*.py.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from benchmarks_md.blender import blender_headline, blender_section, read_blender  # noqa: E402,F401
from benchmarks_md.cleaning import cleaning_section, read_cleaning  # noqa: E402,F401
from benchmarks_md.common import (STAGES, Cell, InputError, fit_exponent, index_cells,  # noqa: E402,F401
                                  read_inputs, read_scrub)
from benchmarks_md.correspondence import (correspondence_requirement, correspondence_section,  # noqa: E402,F401
                                          read_correspondence)
from benchmarks_md.local_timing import local_timing_section, read_local_timing  # noqa: E402,F401
from benchmarks_md.motion import motion_section, read_motion  # noqa: E402,F401
from benchmarks_md.sequences import read_sequences, sequences_headline, sequences_section  # noqa: E402,F401
from benchmarks_md.speed import frame_cost_section, scrub_section, speed_headline, total_exponent  # noqa: E402,F401
from benchmarks_md.writer import write_report  # noqa: E402


def append_sections(out_path, md):
    """Sections written after write_report's, at the end of the report (issue 31's local
    timing, issue 32's drawing cleaning)."""
    with open(out_path, "a", encoding="utf-8") as f:
        f.write("\n".join(md).rstrip() + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", default="out/benchmarks", help="directory of the raw output")
    parser.add_argument("--output", default="BENCHMARKS.md")
    parser.add_argument("--plots", default="docs/benchmarks", help="directory for the SVG plots")
    args = parser.parse_args()
    try:
        records, polygon_pairs, run = read_inputs(args.data)
        if not records:
            raise InputError(f"{args.data}/morph.jsonl holds no results")
        motion = read_motion(args.data)
        correspondence = read_correspondence(args.data)
        scrub = read_scrub(args.data)
        sequences = read_sequences(args.data)
        blender = read_blender(args.data)
        local_timing = read_local_timing(args.data)
        cleaning = read_cleaning(args.data)
        write_report(records, polygon_pairs, run, args.output, args.plots, motion, correspondence, scrub,
                     sequences, blender)
        append_sections(args.output, local_timing_section(local_timing, args.output, args.plots))
        append_sections(args.output, cleaning_section(cleaning, args.output, args.plots))
    except (InputError, KeyError) as error:
        print(f"error: make_benchmarks: incomplete benchmark data: {error}", file=sys.stderr)
        return 2
    print(f"wrote {args.output} and {args.plots}/*.svg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
