"""Experiments on the simulator: many matches run and stored, studies, benchmarks and the
``soccer-sim`` command line.

Layers (a module imports only from its own layer or the ones above it in this list):

* the core, used by everything below: :mod:`experiments.errors` (the error root),
  :mod:`experiments.configuration` (the match configuration of a cycle count),
  :mod:`experiments.limits` (the range of every numeric option), :mod:`experiments.runner` (match specs and
  running them), :mod:`experiments.results` (the results store) and :mod:`experiments.stats`;
* :mod:`experiments.studies` and :mod:`experiments.benchmarks`, each a sub-command module
  (``add_arguments``/``run``) built on the core and the command-line helpers of
  :mod:`experiments.commands` (error lines, shared run options);
* :mod:`experiments.commands` and :mod:`experiments.cli`: the command line, which loads the
  study and benchmark modules by name only when one is chosen.

The core never imports the command line, a study or a benchmark: a library caller gets errors
in terms of parameters, and the command line words them as options.
"""
