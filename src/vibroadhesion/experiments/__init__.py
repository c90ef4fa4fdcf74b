"""What the pipeline asks of the models: pull-off in physical units, the Gent–Schultz fit, the virtual
pull-off experiment, the validation of every level against the simulation, identifiability and
speed against error. No file I/O.

Layer 4: imports from every layer below.
"""

__all__ = ["pulloff", "fitting", "virtual_pulloff", "validation", "identifiability", "benchmarking"]
