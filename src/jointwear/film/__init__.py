"""Lubricant films solved ahead of a run.

``reynolds`` solves the finite journal bearing's Reynolds equation; ``impedance`` tabulates
its film force for the kernels.
"""
