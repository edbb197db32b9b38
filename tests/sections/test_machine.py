"""A machine of several axes on one DC bus (calc.sections.machine, python -m calc machine): two
typed axes whose braking the other takes, worked by hand; the shipped example; bad machine files
named in one sentence."""

import json

import numpy as np
import pytest

from calc.__main__ import main
from calc.core.errors import CalcError
from calc.domain.drive import bus_powers, bus_total
from calc.sections.machine import machine

from ..conftest import ROOT

# A typed axis driven directly: 2 N·m at 1000 rpm (209.44 W) for 1 s, then −2 N·m at 1000 rpm
# (braking, −209.44 W) for 1 s: its cycle is 2 s.
AXIS = """
title = "axis {name}"
[motor]
peak_torque = "10 N*m"
rated_torque = "5 N*m"
[[profile]]
phase = "const"
duration = "1 s"
speed = "1000 rpm"
torque = "2 N*m"
[[profile]]
phase = "decel"
duration = "1 s"
speed = "1000 rpm"
torque = "-2 N*m"
"""
P = 2 * 1000 * 2 * np.pi / 60  # 209.44 W


def write_machine(tmp_path, starts, cycle="2 s", bus=""):
    for k in range(len(starts)):
        (tmp_path / f"a{k}.toml").write_text(AXIS.format(name=k), encoding="utf-8")
    text = f'title = "two axes"\ncycle = "{cycle}"\n' + "".join(
        f'[[axis]]\ncase = "a{k}.toml"\nstart = "{s}"\n' for k, s in enumerate(starts)) + bus
    path = tmp_path / "machine.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_two_axes_whose_braking_the_other_takes(tmp_path):
    # Started 1 s apart, one axis drives 209.44 W while the other brakes 209.44 W: the sum is zero at
    # every moment, nothing is given back to the bus and nothing reaches the resistor.
    bus = '[dc_bus.brake_resistor]\nresistance = "100 ohm"\ncontinuous_power = "10 W"\npeak_power = "1 kW"\n'
    m = machine(write_machine(tmp_path, ["0 s", "1 s"], bus=bus)).to_json()
    b = m["dc_bus"]
    assert b["braking_energy_per_cycle"]["value"] == pytest.approx(0.0, abs=1e-9)
    assert b["peak_power"]["value"] == pytest.approx(0.0, abs=1e-9)
    assert b["resistor_average_power"]["value"] == pytest.approx(0.0, abs=1e-9)
    assert m["verdict"]["passes"] is True
    # Started together, both brake at once: 2 · 209.44 W · 1 s = 418.88 J per 2 s cycle given back,
    # no DC-link energy known (taken as 0 J): 209.44 W on average against the resistor's 10 W.
    m = machine(write_machine(tmp_path, ["0 s", "0 s"], bus=bus)).to_json()
    b = m["dc_bus"]
    assert b["braking_energy_per_cycle"]["value"] == pytest.approx(2 * P, rel=1e-9)
    assert b["peak_power"]["value"] == pytest.approx(2 * P, rel=1e-9)
    assert b["resistor_average_power"]["value"] == pytest.approx(P, rel=1e-9)
    avg = b["checks"][0]
    assert avg["passes"] is False and avg["utilization"] == pytest.approx(P / 10, rel=1e-9)
    assert m["verdict"]["passes"] is False


def test_the_dc_links_take_a_net_event(tmp_path):
    # Half a second apart: A drives over [0, 1) s and brakes over [1, 2); B drives over [0.5, 1.5) and
    # brakes over [1.5, 2) and [0, 0.5). The sum: 0 over [0, 0.5), +2P over [0.5, 1), 0 over [1, 1.5),
    # −2P over [1.5, 2): one net event of 2 · 209.44 W · 0.5 s = 209.44 J; a bus absorbing 100 J
    # leaves 109.44 J per 2 s cycle.
    bus = '[dc_bus]\ndc_link_energy = "100 J"\n'
    b = machine(write_machine(tmp_path, ["0 s", "0.5 s"], bus=bus)).to_json()["dc_bus"]
    assert b["braking_energy_per_cycle"]["value"] == pytest.approx(P, rel=1e-9)
    assert b["resistor_energy_per_cycle"]["value"] == pytest.approx(P - 100, rel=1e-9)


def test_the_sum_from_the_edges_is_the_sum_of_the_rows():
    # Five axes of random steps, cycles 2, 1 and 0.5 s, random starts: the sum from the edges alone
    # (bus_total) equals the rows summed on the common time base (bus_powers) in energy and peak.
    rng = np.random.default_rng(7)
    samples = []
    for cycle in (2.0, 1.0, 0.5, 2.0, 1.0):
        dt = rng.uniform(0.01, 0.2, 40)
        samples.append((dt / dt.sum() * cycle, rng.normal(0, 100, 40)))
    starts = [0.0, 0.3, 0.11, 1.7, 0.05]
    t1, p1 = bus_total(samples, starts, 2.0)
    t2, rows = bus_powers(samples, starts, 2.0)
    p2 = rows.sum(axis=0)
    assert (p1 * np.diff(t1)).sum() == pytest.approx((p2 * np.diff(t2)).sum(), rel=1e-6, abs=1e-6)
    assert p1.max() == pytest.approx(p2.max(), rel=1e-12)
    assert p1.min() == pytest.approx(p2.min(), rel=1e-12)


def test_the_shipped_machine(capsys, tmp_path):
    pdf = tmp_path / "machine.pdf"
    code = main(["machine", str(ROOT / "cases" / "machines" / "two-axes.toml"), "--json", "--pdf", str(pdf)])
    out = json.loads(capsys.readouterr().out)
    assert code == 0 and pdf.stat().st_size > 0
    assert [a["case"] for a in out["axes"]] == ["cases/ball-screw-direct.toml", "cases/indexing-table.toml"]
    assert set(out["dc_bus"]) >= {"peak_power", "average_power", "braking_energy_per_cycle", "resistor_average_power",
                                  "checks"}
    assert out["verdict"]["passes"] is True


@pytest.mark.parametrize("cycle, axis, fragment", [
    ("3 s", "a0.toml", "axis[1].case: the axis's cycle of 2 s does not divide the machine's cycle of 3 s (cycle)"),
    ("2 s", "missing.toml", "axis[1].case: the axis's case file does not read: "),
])
def test_bad_machines_are_one_sentence(tmp_path, capsys, cycle, axis, fragment):
    path = write_machine(tmp_path, ["0 s"], cycle=cycle)
    path.write_text(path.read_text().replace("a0.toml", axis))
    with pytest.raises(CalcError) as err:
        machine(path)
    assert str(path) in str(err.value) and fragment in str(err.value)
    assert main(["machine", str(path)]) == 2
    assert capsys.readouterr().err.startswith(f"error: {path}")


def test_a_machine_file_that_does_not_read(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text("cycle = ", encoding="utf-8")
    with pytest.raises(CalcError, match="TOML syntax error"):
        machine(path)
    with pytest.raises(CalcError, match=r"cannot read the machine file \(FileNotFoundError\)"):
        machine(tmp_path / "none.toml")
    path.write_text('cycle = "2 s"\n', encoding="utf-8")
    with pytest.raises(CalcError, match=r"axis: expected one \[\[axis\]\] table per axis, found none"):
        machine(path)


def test_an_axis_without_a_motor(tmp_path):
    path = write_machine(tmp_path, ["0 s"])
    (tmp_path / "a0.toml").write_text(AXIS.split("[motor]")[0] + '[gearbox]\nratio = 5\n'
                                      + "[[profile]]" + AXIS.split("[[profile]]", 1)[1], encoding="utf-8")
    with pytest.raises(CalcError, match=r"axis\[1\].case: expected a case whose motor's torques are known"):
        machine(path)
