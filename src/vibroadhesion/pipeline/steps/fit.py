"""Step of rule ``fit_gent_schultz``: least-squares Gent–Schultz fit of every model level (Sec. 3.4)."""

from __future__ import annotations

from pathlib import Path

from vibroadhesion.core.levels import names
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.numerics.progress import Heartbeat
from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.artefacts import write_json


def fit(setup_json: str | Path, pulloff_csv: str | Path, out: str | Path, figures_use: str) -> None:
    """Fit w0, n, v0 to the measured rows with each model level (Eqs. 71-72, 106).

    No rows: the published parameters pass through. ``figures_use`` names the fit the figures take their parameters
    from; the summary's status is that fit's (``fitted``, ``at_bound``, ``not_identifiable``, ``failed``: then the
    figures show the published values). A level that fails does not stop the others. A long search prints a
    heartbeat line to the log at most every 10 s (:class:`~vibroadhesion.numerics.progress.Heartbeat`).
    """
    setup = data.read_canonical_setup(setup_json)
    rows = data.read_canonical_pulloff(pulloff_csv)
    published = GentSchultzParameters(setup.w0, setup.n, setup.v0)
    geometry = {"radius": setup.radius, "reduced_modulus": setup.reduced_modulus}
    fits = {model: fit_gent_schultz(rows, model, published, **geometry, progress=Heartbeat(f"fit {model}"))
            for model in names("fit")}
    summary = {
        "data_rows": len(rows),
        "status": ("published parameters passed through (no measured rows)" if rows.empty
                   else f"the figures' {figures_use} fit: {fits[figures_use]['status']}"),
        "published": {"w0": setup.w0, "n": setup.n, "v0": setup.v0,
                      "source": setup.sources["gent_schultz_published.w0"]},
        "figures_use": figures_use,
        "fits": fits,
    }
    write_json(summary, out)
    for model, result in fits.items():
        p = result["parameters"]
        print(f"{model}: {result['status']}; w0 = {p['w0']['estimate']:.6g} J/m^2, n = {p['n']['estimate']:.6g}, "
              f"v0 = {p['v0']['estimate']:.6g} m/s; {result['v0_note']}")
