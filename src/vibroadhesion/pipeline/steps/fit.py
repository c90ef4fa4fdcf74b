"""Step of rule ``fit_gent_schultz``: least-squares Gent–Schultz fit of every model level (Sec. 3.4)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from vibroadhesion.core.levels import names
from vibroadhesion.experiments.fit_statistics import Settings
from vibroadhesion.experiments.fit_summary import figures_choice, start_from_fit
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.numerics.progress import Heartbeat
from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.artefacts import write_json
from vibroadhesion.pipeline.input_checks import schema_validator


def fit(setup_json: str | Path, pulloff_csv: str | Path, out: str | Path, figures_use: str,
        settings: Mapping[str, float] | None = None) -> None:
    """Fit w0, n, v0 to the measured rows with each model level (Eqs. 71-72, 106); results/fit/gent_schultz.json.

    No rows: the published parameters pass through. The cheaper levels are fitted first; what each determined
    (published values elsewhere) is a start point of the simulation's search
    (:func:`~vibroadhesion.experiments.fit_summary.start_from_fit`). ``figures_use`` names the level the figures
    prefer; they use it if its fit is ``fitted``, else the most faithful fitted level, else the published set
    (:func:`~vibroadhesion.experiments.fit_summary.figures_choice`), and the summary says which and why.
    ``settings``: ``relative_scatter``, ``alpha``, ``confidence`` of workflow/config.yaml (fit; None: the defaults of
    :class:`~vibroadhesion.experiments.fit_statistics.Settings`, which are the config's). A level that fails
    does not stop the others. A long search prints a heartbeat line to the log at most every 10 s.
    """
    setup = data.read_canonical_setup(setup_json)
    rows = data.read_canonical_pulloff(pulloff_csv)
    published = GentSchultzParameters(setup.w0, setup.n, setup.v0)
    judged = Settings() if settings is None else Settings(
        confidence=settings["confidence"], stated_scatter=settings["relative_scatter"], alpha=settings["alpha"])
    geometry = {"radius": setup.radius, "reduced_modulus": setup.reduced_modulus}
    fits: dict[str, dict[str, Any]] = {}
    levels = names("fit")
    for model in sorted(levels, key=("simulation",).__contains__):  # the cheaper levels first (a stable sort)
        starts = [start for f in fits.values() if (start := start_from_fit(f, published)) is not None]
        fits[model] = fit_gent_schultz(rows, model, published, **geometry, settings=judged, starts=starts,
                                       progress=Heartbeat(f"fit {model}"))
    used, reason = figures_choice(fits, figures_use)
    summary: dict[str, Any] = {
        "data_rows": len(rows),
        "status": ("published parameters passed through (no measured rows)" if rows.empty
                   else f"the figures use {'the published parameters' if used == 'published' else f'the {used} fit'}"
                   f": {reason}"),
        "published": {"w0": setup.w0, "n": setup.n, "v0": setup.v0,
                      "source": setup.sources["gent_schultz_published.w0"]},
        "figures_preferred": figures_use,
        "figures_use": used,
        "figures_reason": reason,
        "settings": {"confidence": judged.confidence, "relative_scatter": judged.stated_scatter,
                     "alpha": judged.alpha, "max_relative_se": judged.max_relative_se},
        "fits": {model: fits[model] for model in levels},
    }
    errors = sorted(schema_validator("fit").iter_errors(summary), key=str)
    if errors:  # a defect of the fit's code, never of the user's rows: stop before writing
        raise ValueError(f"the fit summary does not match pipeline/schemas/fit.schema.json: {errors[0].message}")
    write_json(summary, out)
    for model, result in summary["fits"].items():
        p = result["parameters"]
        print(f"{model}: {result['status']}; w0 = {p['w0']['estimate']:.6g} J/m^2, n = {p['n']['estimate']:.6g}, "
              f"v0 = {p['v0']['estimate']:.6g} m/s; {result['v0_note']}")
