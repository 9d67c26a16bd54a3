"""Parameter sweeps: many runs of one model with some values varied, and their table.

``study`` has ``sweep`` (also ``jointwear.sweep``): it checks every case, skips those done
before, runs the others and writes the table; ``cases`` names the cases and their overrides;
``runners`` runs them in this process, in local processes or on a Dask cluster.
"""
