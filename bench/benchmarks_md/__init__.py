"""The writer of BENCHMARKS.md, one module per part of the report (bench/make_benchmarks.py
is the command; bench/README.md lists the modules):

  common.py          matplotlib set-up, constants, reading morph.jsonl / polygon_pairs.json /
                     run.json / scrub.jsonl, the cells, number formats, Markdown tables, log-log plots
  writer.py          write_report: the header, headline, corpus, peak memory and straight-line morph,
                     and the order of the sections
  steiner.py         Steiner vertices per method and the polygon-pair corpus
  stages.py          time per stage, fitted growth exponents, where the time goes, per-frame plots
  speed.py           issue 15: a frame against a fresh LU, scrubbing, the total's growth
  motion.py          motion quality (issue 12) from motion.json
  correspondence.py  correspondence against size (issue 13) from correspondence.json
  sequences.py       key poses (issue 28) from sequences.json: smoothness at the keys, filmstrip
  local_timing.py    local timing (issue 31) from local_timing.json: the measured lag of a delayed
                     limb against the overlap asked, filmstrips (make_benchmarks.py appends it)
  cleaning.py        drawing cleaning (issue 32) from cleaning.json: planted defects found, validity,
                     changes reported, idempotence, a drawing before and after (appended after it)
"""
