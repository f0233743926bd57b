"""Regenerate the generated documentation: docs/examples.md (+ docs/img/) and docs/mechanism_*.md.

    python docs/make_examples.py              # everything
    python docs/make_examples.py --pages      # only the mechanism pages (fast)

Each deck in decks/ is run as shipped; its published numbers (Ball 1988, Yang 1992) are put
beside camtrain's. A deck that cannot run yet, or a quantity camtrain does not compute yet, is
written as "not yet computed" with the reason, so rerunning this script after the physics lands
fills the gaps without editing anything by hand.
"""
from __future__ import annotations

import argparse
import math
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
IMG = DOCS / "img"
sys.path.insert(0, str(ROOT))

NOT_YET = "not yet computed"

#: deck stem -> (what it is, [(quantity, published value, unit, source, camtrain metric)]).
#: The metric is a camtrain metric name, or "rb_min" (change of r_B to the convexity limit, %).
PUBLISHED = {
    "harrison_flat": ("Ball's datum case: cam and flat-faced follower, Paul Harrison's data, "
                      "2500 rpm camshaft.", [
                          ("frictional power loss", 48.50, "W", "Ball 1988, Fig 5.1 header",
                           "power_loss_mean"),
                          ("valve-bounce camshaft speed", 3600.0, "rpm",
                           "Ball 1988 text: ≈ 60 Hz camshaft, read from a plot", "bounce_speed"),
                          ("smallest base radius for a convex cam", -20.0, "%",
                           "Ball 1988 text: 'a decrease of just over 20 %'", "rb_min"),
                      ]),
    "pinto_finger": ("Ford 2.0 l Pinto inlet cam and end-pivoted finger follower, datum design, "
                     "2500 rpm camshaft.", [
                         ("frictional power loss", 166.14, "W", "Ball 1988, Fig 5.15 header",
                          "power_loss_mean"),
                         ("valve-bounce camshaft speed", 3750.0, "rpm",
                          "Ball 1988 text (its Hz and rpm figures disagree)", "bounce_speed"),
                     ]),
    "pinto_finger_improved": ("Ball's improved Pinto design (k −10 %, r_f +20 %, r_B +12 %), "
                              "2500 rpm camshaft.", [
                                  ("frictional power loss", 160.89, "W",
                                   "Ball 1988, Fig 5.22 header", "power_loss_mean"),
                                  ("valve-bounce camshaft speed (lower bound)", 3300.0, "rpm",
                                   "Ball 1988 text: still above 110 Hz engine", "bounce_speed"),
                              ]),
    "rover_2300_rocker": ("Rover 2300 cam and centrally pivoted rocker (Lim et al. 1983 data), "
                          "2500 rpm camshaft.", [
                              ("frictional power loss", 58.78, "W", "Ball 1988, Fig 5.9 header",
                               "power_loss_mean"),
                          ]),
    "desmo_rig": ("Ball's desmodromic rig: opening cam on a centrally pivoted follower, closing "
                  "cam on an end-pivoted follower, 2000 rpm camshaft.", [
                      ("frictional power loss, opening pair", 1.82, "W",
                       "Ball 1988, Fig F.1a header", "power_loss_mean"),
                      ("frictional power loss, closing pair", 6.46, "W",
                       "Ball 1988, Fig F.2a header", "closing_power_loss_mean"),
                  ]),
    "zeta_intake": ("Ford 1.8 l Zeta intake cam, tapered, on a domed follower, 1500 rpm "
                    "camshaft.", [
                        ("frictional power loss per cam", 39.68, "W", "Yang 1992, Fig 4.2",
                         "power_loss_mean"),
                    ]),
    "zeta_intake_camshaft": ("The whole Zeta intake camshaft: eight intake cams and five plain "
                             "bearings, 1500 rpm camshaft. camtrain's drive power is the "
                             "cycle mean of the summed lobe torques, which over a cycle is the "
                             "friction of the eight contacts.", [
                                 ("frictional power loss per cam", 39.68, "W",
                                  "Yang 1992, Fig 4.2", "power_loss_mean"),
                                 ("8 cams/followers", 317.5, "W", "Yang 1992, Fig 4.7",
                                  "drive_power_mean"),
                                 ("5 camshaft bearings", 22.0, "W", "Yang 1992, Fig 4.7",
                                  "bearings_power_total"),
                                 ("bearing 1, dynamic", 5.0, "W", "Yang 1992, Table 4.1",
                                  "bearing_1_power_mean"),
                                 ("bearing 2, dynamic", 4.2, "W", "Yang 1992, Table 4.1",
                                  "bearing_2_power_mean"),
                                 ("bearing 3, dynamic", 4.3, "W", "Yang 1992, Table 4.1",
                                  "bearing_3_power_mean"),
                                 ("bearing 1, Petroff", 2.7, "W", "Yang 1992, Table 4.1",
                                  "bearing_1_petroff_power"),
                                 ("bearing 2, Petroff", 2.2, "W", "Yang 1992, Table 4.1",
                                  "bearing_2_petroff_power"),
                             ]),
    "zeta_exhaust": ("Ford 1.8 l Zeta exhaust cam, tapered, on a domed follower, 1500 rpm "
                     "camshaft. Yang prints results for the intake cam only, so there is no "
                     "published number to compare with.", []),
    "bearing_ocvirk_check": ("A stand-alone short journal bearing under a constant 500 N load: "
                             "a check against Ocvirk's closed-form short-bearing solution "
                             "(not a published result of the sources).", [
                                 ("eccentricity ratio", 0.7165, "-", "Ocvirk short bearing",
                                  "max_eccentricity"),
                                 ("minimum film", 7.09, "µm", "Ocvirk short bearing",
                                  "min_film"),
                                 ("Petroff power", 2.180, "W", "Petroff", "petroff_power"),
                             ]),
}

#: factor from a metric's SI unit to the unit of the published value
_FACTOR = {"µm": 1e6, "W": 1.0, "rpm": 1.0, "-": 1.0}

#: camtrain metrics shown for every deck (name, label, unit shown, factor from SI)
SHOWN = [("max_lift", "maximum lift", "mm", 1e3),
         ("power_loss_mean", "mean frictional power loss", "W", 1.0),
         ("film_min_at_max_lift", "h_min at maximum lift", "µm", 1e6),
         ("hertz_at_max_lift", "Hertz p_max at maximum lift", "MPa", 1e-6),
         ("hertz_max", "largest Hertz p_max", "MPa", 1e-6),
         ("load_max", "largest contact load", "N", 1.0),
         ("bounce_speed", "valve-bounce camshaft speed", "rpm", 1.0)]

SHEETS_SHOWN = ("contact", "friction")


def _extract(metric: str, unit: str, result, deck) -> float | None:
    m = result.metrics if result is not None else {}
    if metric == "rb_min":
        if "min_base_radius_convex" not in m:
            return None
        rb = deck.cam.base_radius
        return 100.0 * (m["min_base_radius_convex"].value - rb) / rb
    if metric not in m or not math.isfinite(m[metric].value):
        return None
    return m[metric].value * _FACTOR.get(unit, 1.0)


def _num(x: float | None, digits: int = 4) -> str:
    if x is None or not math.isfinite(x):
        return NOT_YET
    from camtrain.report.display import fmt

    return fmt(x, digits)


def _run(path: Path):
    from camtrain import api
    from camtrain.errors import CamtrainError

    loaded = api.load(path)
    try:
        return loaded, api.run(loaded), ""
    except CamtrainError as exc:
        return loaded, None, str(exc)


def _images(stem: str, result, loaded) -> list[tuple[str, str]]:
    from camtrain.report.sheets import write_plots

    IMG.mkdir(exist_ok=True)
    shown = []
    with tempfile.TemporaryDirectory() as tmp:
        write_plots(result, loaded.model, Path(tmp), formats=("png",), sha=loaded.sha256,
                    dpi=100)
        picks = [(f"sheet_{s}.png", f"{stem}_{s}.png", s) for s in SHEETS_SHOWN]
        picks.append(("panels/profile.png", f"{stem}_profile.png", "profile"))
        for src, dst, what in picks:
            if (Path(tmp) / src).exists():
                _compact_png(Path(tmp) / src, IMG / dst)
                shown.append((dst, what))
    return shown


def _compact_png(src: Path, dst: Path) -> None:
    """A 256-colour copy: line plots lose nothing visible and the repository stays small."""
    from PIL import Image

    with Image.open(src) as img:
        img.convert("RGB").quantize(colors=256, dither=Image.Dither.NONE).save(dst, optimize=True)


def deck_section(path: Path) -> list[str]:
    stem = path.stem
    what, published = PUBLISHED.get(stem, ("", []))
    loaded, result, error = _run(path)
    lines = [f"## {loaded.model.title}", "", f"Deck: `decks/{path.name}`. {what}", "",
             "```sh", f"camtrain run decks/{path.name} --out out/{stem}", "```", ""]
    if error:
        lines += [f"camtrain cannot run this deck yet: {error}. Every camtrain value below is "
                  f"therefore {NOT_YET}.", ""]
    if published:
        lines += ["| quantity | published | source | camtrain | difference |",
                  "|---|---|---|---|---|"]
        for name, value, unit, source, kind in published:
            ours = _extract(kind, unit, result, loaded.model)
            diff = ""
            if ours is not None and unit != "%" and value:
                rel = 100.0 * (ours - value) / value
                diff = "0.0 %" if abs(rel) < 0.05 else f"{rel:+.1f} %"
            elif ours is not None:
                diff = f"{ours - value:+.1f} points"
            u = "" if unit == "-" else f" {unit}"
            ours_text = NOT_YET if ours is None else f"{_num(ours)}{u}"
            lines.append(f"| {name} | {value:g}{u} | {source} | {ours_text} | {diff} |")
        lines.append("")
    have = [row for row in SHOWN if result is not None and row[0] in result.metrics]
    if have or error:
        missing = NOT_YET if (error or result.not_available) else "not computed for this deck"
        lines += ["camtrain's key numbers for this deck:", "", "| quantity | camtrain |",
                  "|---|---|"]
        for name, label, unit, factor in SHOWN:
            m = result.metrics.get(name) if result is not None else None
            value = None if m is None else m.value * (1.0 if m.unit == "rpm" else factor)
            text = missing if value is None else (
                NOT_YET if not math.isfinite(value) else f"{_num(value)} {unit}")
            lines.append(f"| {label} | {text} |")
        lines.append("")
    if result is not None and "cam_angle" in result.columns:
        for image, what in _images(stem, result, loaded):
            lines += [f"![{stem}: {what}](img/{image})", ""]
    return lines


def examples_md() -> str:
    from camtrain import __version__

    lines = ["# Worked examples", "",
             f"Generated by `python docs/make_examples.py` with camtrain {__version__}; do not "
             "edit by hand. Each data set in `decks/` is run as shipped and the numbers its "
             "source publishes are put beside camtrain's. Where camtrain does not compute a "
             f"quantity yet the table says \"{NOT_YET}\".", "",
             "Published power losses depend on choices the sources do not state (the "
             "entrainment convention, whether the base circle carries friction); the deck "
             "options under `[tribology]` and `[clearance]` select them. Differences of "
             "10–15 % are therefore expected.", ""]
    for path in sorted((ROOT / "decks").glob("*.toml")):
        lines += deck_section(path)
    return "\n".join(lines).rstrip() + "\n"


def write_pages() -> None:
    from camtrain.deck.schema import MECHANISMS
    from camtrain.report.docs_pages import mechanism_page

    for name in MECHANISMS:
        (DOCS / f"mechanism_{name}.md").write_text(mechanism_page(name), encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pages", action="store_true", help="only the mechanism pages")
    args = parser.parse_args()
    write_pages()
    if not args.pages:
        (DOCS / "examples.md").write_text(examples_md(), encoding="utf-8")


if __name__ == "__main__":
    main()
