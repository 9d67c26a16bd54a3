"""Running a model, and what watches a run.

``simulate``: the compiled loop chunk by chunk; ``run_file``: a model file to a results folder;
``energy``, ``finite``, ``interrupts``, ``status``: the checks, signals and outcomes of a run.
"""
