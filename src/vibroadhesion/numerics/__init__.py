"""Physics-free numerics: bracketed roots, pseudo-arclength continuation, progress reporting.

Layer 0: imports nothing from the rest of the package.
"""

__all__ = ["roots", "continuation", "progress"]
