"""Long-life wear: simulate a few steady cycles, extrapolate their wear, update, repeat.

``study`` has ``life`` (also ``jointwear.life``) and describes the method; ``settings``
checks its settings, ``update`` carries out one update, ``records`` makes the rows and the
summary, and ``files`` keeps the run's folder and checkpoint.
"""
