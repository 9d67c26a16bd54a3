"""Figures and the animation: the only part of jointwear that imports matplotlib.

Figures see ``Results`` and the studies' tables (the model's own names and SI columns),
never the kernel arrays.
"""
