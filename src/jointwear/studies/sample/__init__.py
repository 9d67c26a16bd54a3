"""Sampled studies: inputs drawn from distributions, and the statistics of the results.

``study`` has ``sample`` (also ``jointwear.sample``); ``distributions`` reads the inputs'
distributions, ``design`` draws the points (random, Latin hypercube, Sobol', Saltelli),
``plan`` reads options and study files, ``statistics`` and ``sensitivity`` analyse the table.
"""
