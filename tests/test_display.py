"""Display units: one choice for the session, applied by every formatter and label."""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import display
from vbi_lib import units as u


@pytest.fixture(autouse=True)
def back_to_si():  # noqa: ANN201
    yield
    display.set_units("SI")


def test_us_customary_with_si_alongside() -> None:
    display.set_units("US")
    assert display.fmt(100 * u.ft, "length") == "100 ft (30.5 m)"
    assert display.fmt(60 * u.mph, "speed") == "60 mph (96.6 km/h)"
    assert display.label("deflection", "deflection") == "deflection [in]"
    assert display.value(1 * u.kip, "force") == pytest.approx(1.0)


def test_si_with_us_alongside_and_without() -> None:
    display.set_units("SI")
    assert display.fmt(30.48, "length") == "30.5 m (100 ft)"
    display.set_units("SI", alongside=False)
    assert display.fmt(30.48, "length") == "30.5 m"
    assert display.fmt(0.05, "damping_ratio") == "5 %"


def test_every_system_defines_every_quantity() -> None:
    for system in display.SYSTEMS.values():
        assert set(system.units) == set(display.QUANTITIES)


def test_unknown_choices_are_named() -> None:
    with pytest.raises(ValueError, match="system='metric'"):
        display.set_units("metric")
    with pytest.raises(ValueError, match="quantity='lenght'"):
        display.symbol("lenght")


# ---------------------------------------------------------------------------- book tables
def test_table_is_a_numbered_myst_table_with_units_in_its_header() -> None:
    import pandas as pd

    display.set_units("US")
    frame = pd.DataFrame(
        {
            display.label("span", "length"): display.value(np.array([12.192, 30.48]), "length"),
            "bridge": ["40 ft | path 1", "100 ft"],
            "lost contact": [True, False],
        },
        index=pd.Index([1, 2], name="row"),
    )
    text = display.table(frame, "Two of the study's beams.", "table-two-beams").markdown
    lines = text.splitlines()
    assert lines[0] == ":::{table} Two of the study's beams."
    assert lines[1] == ":name: table-two-beams"
    assert lines[3] == "| row | span [ft] | bridge | lost contact |"
    assert lines[4] == "|---:|---:|:---|:---|"  # numbers right, text left
    assert lines[5] == r"| 1 | 40 | 40 ft \| path 1 | yes |"  # a pipe in a cell is escaped
    assert lines[6] == "| 2 | 100 | 100 ft | no |"
    assert lines[-1] == ":::"
    shown = display.table(frame, "c", "table-x", number_format="{:.2f}", index=False)
    assert shown.markdown.splitlines()[3] == "| span [ft] | bridge | lost contact |"
    assert "| 40.00 |" in shown.markdown
    assert shown._repr_markdown_() == shown.markdown


def test_table_refuses_what_it_cannot_show() -> None:
    import pandas as pd

    frame = pd.DataFrame({"a": [1.0]})
    with pytest.raises(TypeError, match="frame=list must be a pandas DataFrame"):
        display.table([1, 2], "c", "table-a")
    with pytest.raises(ValueError, match="name='Table 1' must be a label"):
        display.table(frame, "c", "Table 1")
    with pytest.raises(ValueError, match="caption='' must be one line"):
        display.table(frame, "", "table-a")
    with pytest.raises(ValueError, match="frame has no rows"):
        display.table(frame.iloc[:0], "c", "table-a")


def test_table_writes_integers_as_integers() -> None:
    import pandas as pd

    frame = pd.DataFrame({"spans": [1, 2], "DAF [-]": [1.0, 2.5]})
    text = display.table(frame, "c", "table-ints", number_format="{:.2f}", index=False)
    assert "| 1 | 1.00 |" in text.markdown and "| 2 | 2.50 |" in text.markdown


def test_table_formats_each_column_to_its_meaning() -> None:
    import pandas as pd

    frame = pd.DataFrame(
        {
            ("mode 1", "deflection"): [0.5, np.nan],
            ("mode 1", "moment"): [0.25, 0.125],
            "span [ft]": [40.0, 100.0],
        }
    )
    text = display.table(
        frame,
        "c",
        "table-formats",
        index=False,
        formats={"span [ft]": "{:.0f}", "mode 1, moment": lambda v: f"{100 * v:.0f} %"},
    ).markdown
    lines = text.splitlines()
    assert lines[3] == "| mode 1, deflection | mode 1, moment | span [ft] |"
    assert lines[5] == "| 0.5 | 25 % | 40 |"
    assert lines[6] == f"| {display.MISSING} | 12 % | 100 |"  # NaN is a dash, not "nan"
    with pytest.raises(ValueError, match=r"formats=\['span'\] name no column"):
        display.table(frame, "c", "table-formats", formats={"span": "{:.0f}"})


def test_short_values_follow_the_display_units() -> None:
    display.set_units("US")
    assert display.short(30.48, "length") == "100.0 ft"
    assert display.short(7.5e12 * u.lbf * u.inch**2, "flexural_rigidity") == "7.500e+12 lbf in²"
    display.set_units("SI")
    assert display.short(30.48, "length") == "30.48 m"
    assert display.short(2303.0, "mass_per_length") == "2303 kg/m"
    assert display.short(0.0, "length") == "0 m"


def test_reprs_follow_the_display_units() -> None:
    import vbi_lib as vbi

    bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 4.5, 0.10, damped=True)
    road = vbi.Profile.flat(650 * u.ft, 1 * u.inch)
    display.set_units("US")
    assert "1 span x 100.0 ft" in repr(bridge) and "lbf in²" in repr(bridge)
    assert "m = 200.0 slinch (weight 77.22 kip)" in repr(truck)
    assert "over 650.0 ft, spacing 1.000 in" in repr(road)
    assert "72.00 kip, wheelbase 28.00 ft" in repr(vbi.vehicles.hs20().system)
    display.set_units("SI")
    assert "1 span x 30.48 m" in repr(bridge) and "N m²" in repr(bridge)
    assert "m = 35.03 t" in repr(truck)
    assert "over 198.1 m, spacing 25.4 mm" in repr(road)
