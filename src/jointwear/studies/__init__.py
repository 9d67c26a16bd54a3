"""Studies built on ``simulate``: parameter sweeps (``sweep``) and long-life wear (``life``)."""
