"""What the pipeline asks of the models; no file I/O.

Pull-off in physical units, the Gent–Schultz fit, the virtual pull-off experiment, the
validation of every level against the simulation, identifiability and speed against error.

Layer 4: imports from every layer below.
"""

__all__ = ["pulloff", "fitting", "virtual_pulloff", "validation", "identifiability", "benchmarking"]
