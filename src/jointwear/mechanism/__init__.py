"""The mechanism as arrays, before the dynamics.

``system``: ``Model`` -> the kernels' tables; ``assembly``: the initial pose and velocities;
``lockup``: where a driven mechanism locks up; ``pattern``: the sparse Jacobian's pattern.
"""
