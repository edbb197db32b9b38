"""The design review's state without its widgets (calc.review.state, calc.review.variants): every
edit a key path written into the case file's text and read again by the case reader, undo and
redo, values typed and refused, variants kept and compared, the address a link carries.

Expected numbers are worked by hand from the example (cases/indexing-table.toml): one index of
90 deg in 0.5 s (ramps 0.15 s, jerk 0.03 s), then a dwell of 1 s, so ED = 0.5 / 1.5 = 33.3 %;
the catalog's motor SGMUH-10DA (T_1B 6.5 N·m) through NPT035-10 (i = 10, η = 0.97).
"""

import json

import pytest

from calc.core.errors import CalcError
from calc.review.edit import Edit, edited_text
from calc.review.inputs import SELECTION
from calc.review.keep import CaseFiles
from calc.review.state import History, ReviewState, added_entries
from calc.review.variants import Variants
from calc.sections import evaluate
from calc.sections.case import read_case

from ..conftest import DERIVED_EXAMPLE, ROOT


@pytest.fixture
def example(tmp_path):
    """The example in a folder of its own (so a saved file lands there), read."""
    path = tmp_path / "axis.toml"
    path.write_text(DERIVED_EXAMPLE.read_text().replace('"../data/', f'"{ROOT}/data/'))
    state = ReviewState(path)
    state.load()
    return state


def results(state: ReviewState) -> dict:
    """The results of the state as it stands, as the JSON contract writes them."""
    screen = state.evaluate()
    assert screen.error is None, screen.error
    return screen.report.evaluated.to_json()


def test_a_dwell_added_is_undone_and_redone(example):
    # A dwell after the last entry, as long as the last dwell (1 s): the cycle 0.5 + 1 + 1 = 2.5 s,
    # ED = 0.5 / 2.5 = 20 %; undone, ED = 0.5 / 1.5 = 33.3 % again.
    assert results(example)["duty"]["ED"]["value"] == pytest.approx(100 / 3)
    assert not example.history.can_undo and example.entries() == ["move", "dwell"]
    example.add_entry(2, "dwell")
    assert example.entries() == ["move", "dwell", "dwell"] and added_entries(example.moves) == {3}
    assert results(example)["duty"]["ED"]["value"] == pytest.approx(20.0)
    assert example.from_edits("move[3].dwell") == "an entry added here: not in the file"
    assert example.from_edits("move[2].dwell") is None
    assert example.modified() and example.changes() == {}  # an edit of the moves, no value changed
    example.undo()
    assert example.entries() == ["move", "dwell"] and not example.modified()
    assert results(example)["duty"]["ED"]["value"] == pytest.approx(100 / 3)
    assert example.history.can_redo and not example.history.can_undo
    example.redo()
    assert example.entries() == ["move", "dwell", "dwell"]
    assert results(example)["duty"]["ED"]["value"] == pytest.approx(20.0)
    # The edit is the file's text: the saved case has the three entries and reads as the screen.
    text = example.case_text()
    assert text.startswith("# Changed in the design review from axis.toml: dwell 1 s added as entry 3\n")
    assert text.count("\n[[move]]\n") == 3 and "# One index: 90 deg in 0.5 s" in text
    saved = example.save("axis-dwell.toml")
    assert evaluate(read_case(saved)).to_json()["duty"] == results(example)["duty"]


def test_a_value_changed_is_written_into_the_file_and_read_again(example):
    # The index in 1.0 s: peak speed φ / (t − t_a) = (π/2) / (1.0 − 0.15) = 1.8480 rad/s = 17.65 rpm
    # (the S-curve's ramps keep the trapezoid's mean); cycle 2 s, Z_h = 1800 /h, f_s = 1.3 (E4), so
    # T_2max = 6.5 · 10 · 1.3 · 0.97 = 81.97 N·m (it was 100.9 N·m with f_s = 1.6 at 2400 /h).
    before = results(example)
    assert before["cyclic"]["T2max"]["value"] == pytest.approx(100.88, abs=0.01)
    assert example.type_text("move[1].time", "1")
    assert example.changes() == {"move[1].time": (1.0, "s")} and example.texts["move[1].time"] == "1"
    after = results(example)
    assert after["motion"]["peak_speed"]["value"] == pytest.approx(17.647, abs=0.001)
    assert after["cyclic"]["T2max"]["value"] == pytest.approx(81.965, abs=0.01)
    assert example.changed_case().motion.tables["move"][0]["time"] == "1 s"  # read from the text, as saved
    text = example.case_text()
    assert text.startswith("# Changed in the design review from axis.toml: move[1].time 0.5 s -> 1 s\n")
    assert 'time = "1 s"' in text
    assert example.shown.text == text  # the screen's case is read from the text saved
    # The same value again changes nothing; back to the file's value, the case is the file's.
    assert not example.type_text("move[1].time", "1")
    example.type_text("move[1].time", "0.5")
    assert example.changes() == {} and example.changed_case() is example.case


def test_a_refused_text_changes_no_value_and_a_decimal_comma_is_a_point(example):
    assert example.type_text("mechanism.inertia", "abc")  # the results say it was refused
    assert example.values["mechanism.inertia"] == 1500.0 and example.texts["mechanism.inertia"] == "abc"
    assert "is not a number" in example.refused["mechanism.inertia"][1]
    with pytest.raises(CalcError, match="a refused value is in a field"):
        example.save("never.toml")
    example.set_value("mechanism.inertia", 1600.0)  # a slider moved: the refused text stays in its field
    assert example.texts["mechanism.inertia"] == "abc"
    assert example.type_text("mechanism.inertia", "1550,5")
    assert example.values["mechanism.inertia"] == 1550.5
    assert example.texts["mechanism.inertia"] == "1550.5" and not example.refused
    assert example.type_text("move[2].dwell", "1e9")
    assert example.values["move[2].dwell"] == 1.0  # out of range: kept, never clamped
    assert "outside the range of 2 dwell: time t" in example.refused["move[2].dwell"][1]


def test_a_forced_gearbox_part_is_a_key_of_the_file(example):
    # NPT025-10 alone: no motor passes with it; the pair closest to passing, SGM7G-03A, fails on
    # T_2max = 5.88 · 10 · 1.6 · 0.97 = 91.26 N·m against its T_2B of 90 N·m.
    example.set_value("gearbox.part", "NPT025-10")
    r = results(example)
    assert r["verdict"]["passes"] is False and r["gearbox"]["selected"] is None
    assert r["motor"]["selected"] == "SGM7G-03A" and r["cyclic"]["T2max"]["value"] == pytest.approx(91.2576)
    assert 'part = "NPT025-10"' in example.case_text()
    assert "gearbox.part (not given) -> NPT025-10" in example.case_text()
    example.set_value("gearbox.part", SELECTION)
    assert example.changes() == {} and results(example)["gearbox"]["selected"] == "NPT035-10"


def test_variants_are_kept_compared_and_carried_by_a_link(example):
    variants = Variants()
    example.evaluate()
    variants.keep(example)
    example.type_text("move[1].time", "1")
    example.evaluate()
    variants.keep(example)
    assert [name for name, _ in variants.kept] == ["1: axis.toml as written", "2: axis.toml with 1 move: time t 1 s"]
    # ED = 1.0 / 2.0 = 50 % and T_2max 81.97 N·m differ from the first.
    compared = variants.comparison("SI")
    assert '<td class="differs">50 %</td>' in compared and '<td class="differs">81.97 N·m</td>' in compared
    assert variants.states[1] == {"case": "axis.toml", "edits": [], "values": {"move[1].time": "1"}}
    # A link's states give the same variants, each evaluated again from its case file.
    again = Variants()
    assert again.follow(json.dumps(variants.states), CaseFiles(example.path)) == []
    assert [name for name, _ in again.kept] == [name for name, _ in variants.kept]
    assert again.comparison("SI") == compared
    missed = again.follow(json.dumps([{"case": "gone.toml", "edits": [], "values": {}}]), CaseFiles(example.path))
    assert missed == ["variant 1: no case file 'gone.toml' among the cases"] and again.kept == []


def test_the_address_of_a_state_gives_the_same_screen(example):
    example.add_entry(1, "move")  # a copy of the first move after it
    example.type_text("move[2].distance", "-90")  # back to where the table started
    example.evaluate()
    address = {"edits": example.shown.moves, "values": example.shown.changed_texts}
    copy = {"distance": "90 deg", "time": "0.5 s", "accel_time": "0.15 s", "jerk_time": "0.03 s"}
    assert address == {"edits": [["add", 1, copy]], "values": {"move[2].distance": "-90"}}
    other = ReviewState(example.path)
    other.load()
    assert other.follow_moves(address["edits"]) and not other.follow_moves(address["edits"])
    other.follow_values(address["values"])
    assert results(other) == results(example)
    # Two moves of 0.5 s and a dwell of 1 s: ED = 1.0 / 2.0 = 50 %.
    assert results(other)["duty"]["ED"]["value"] == pytest.approx(50.0)
    with pytest.raises(CalcError, match=r"^axis.toml has no input move\[9\].time$"):
        other.follow_values({"move[9].time": "1"})


def test_an_edit_that_cannot_be_made_leaves_the_state_as_it_was(example):
    example.remove_entry(2)  # the dwell: one move is left
    with pytest.raises(CalcError, match=r"^axis.toml: move\[1\] is the only \[\[move\]\] table: it cannot be "):
        example.remove_entry(1)
    assert example.entries() == ["move"] and len(example.moves) == 1
    with pytest.raises(CalcError, match=r"^a belt needs its diameter: expected a number above zero \(in mm\), found"):
        example.change_mechanism("belt", "0")
    assert example.case.motion.mechanism.type == "rotary"


def test_the_mechanisms_type_changes_and_is_undone(example):
    # A ball screw of 20 mm lead: the moved mass 0.15 kg·m² / (0.02 m / 2π)² = 14 804.4 kg.
    said = example.change_mechanism("ball-screw", "20")
    assert said.startswith("mechanism rotary -> ball-screw of 20 mm (equivalent at the gearbox output")
    assert example.texts["mechanism.mass"] == "14804.4066"
    assert example.from_edits("mechanism.mass").startswith("set by the change")
    assert example.case.motion.tables["move"][0]["distance"] == "5 mm"  # a quarter turn of 20 mm
    example.undo()
    assert example.case.motion.mechanism.type == "rotary" and example.moves == []


def test_a_segment_of_a_recorded_cycle_types_the_cycle(tmp_path):
    """A drive record of 2 rad/s reached in 1 s, held 1 s, left in 1 s, through a table of
    1500 kg·cm²: segments of 1 s with T = J·α = 0.15 · 2 = 0.3 N·m, 0, −0.3 N·m. A segment's torque
    changed types the cycle: every segment as [[profile]], the record and the mechanism taken out,
    J_L in [load]; the saved file reads as the screen."""
    (tmp_path / "rec.csv").write_text("time [s],speed [rad/s]\n0,0\n1,2\n2,2\n3,0\n")
    path = tmp_path / "rec.toml"
    path.write_text('[gearbox]\nratio = 10\n[mechanism]\ntype = "rotary"\ninertia = "1500 kg*cm**2"\n'
                    '[drive_record]\nfile = "rec.csv"\n')
    state = ReviewState(path)
    state.load()
    assert [(s.key, s.value) for s in state.specs if s.key.endswith("torque")] == [
        ("profile[1].torque", 0.3), ("profile[2].torque", 0.0), ("profile[3].torque", -0.3)]
    state.set_value("profile[1].torque", 9.0)
    assert state.evaluate().typed_by_hand and state.changed_case().motion is None
    text = state.case_text()
    assert text.startswith("# Changed in the design review from rec.toml: [drive_record] taken out; "
                           "[mechanism] taken out; profile written as 3 tables; "
                           "load.inertia (not given) -> 1500 kg*cm**2; profile[1].torque 0.3 N*m -> 9 N*m\n")
    saved = read_case(state.save("typed.toml"))
    assert saved.motion is None and saved.load_inertia.m_as("kg*cm**2") == 1500.0
    assert evaluate(saved).to_json()["continuous"] == results(state)["continuous"]


def test_the_unit_system_follows_the_file():
    inch = ReviewState(ROOT / "cases" / "linear-axis-inch.toml")
    inch.load()
    assert (inch.file_units, inch.units, inch.length_unit()) == ("inch-pound", "inch-pound", "in")
    assert (inch.spec("mechanism.mass").unit, inch.texts["mechanism.mass"]) == ("lb", "60")
    si = ReviewState(DERIVED_EXAMPLE)
    si.load()
    assert (si.file_units, si.units, si.length_unit()) == ("SI", "SI", "mm")


def test_a_case_file_that_cannot_be_read_says_why_and_changes_nothing(example, tmp_path):
    with pytest.raises(CalcError, match=r"^missing.toml: the case file does not exist$"):
        example.load(tmp_path / "missing.toml")
    assert example.path.name == "axis.toml" and example.case is not None


def test_the_history_keeps_each_change_once():
    history = History(("[]", {"a": 1}))
    history.push(("[]", {"a": 1}))  # the same state: no change
    assert not history.can_undo
    history.push(("[]", {"a": 2}))
    history.push(("[]", {"a": 3}))
    assert history.undo() == ("[]", {"a": 2}) and history.can_redo
    history.push(("[]", {"a": 4}))  # a change after an undo drops what was undone
    assert not history.can_redo and history.undo() == ("[]", {"a": 2})
    assert history.undo() == ("[]", {"a": 1}) and history.undo() is None


def test_every_edit_keeps_the_files_comments():
    text = '[motor]\npeak_torque = "12 N*m"  # T_1B\n[gearbox]\nratio = 10  # i\n'
    edited = edited_text(text, [Edit("motor.peak_torque", "16 N*m"), Edit("gearbox.ratio", 8.0)], "a.toml")
    # An integer stays one; a comment beside a value changed stays, marked as said of the file's value.
    assert edited == ('[motor]\npeak_torque = "16 N*m"  # (said of the file\'s value 12 N*m) T_1B\n'
                      '[gearbox]\nratio = 8  # (said of the file\'s value 10) i\n')


def test_an_input_error_is_kept_as_no_variant_and_a_links_variant_says_it(example):
    # 0.3 s + 0.3 s of ramps do not fit in the move's 0.5 s: the screen is an input error.
    variants = Variants()
    with pytest.raises(CalcError, match=r"^the inputs give no design \(an input error\)$"):
        variants.keep(example)  # nothing evaluated yet
    example.type_text("move[1].accel_time", "0.3")
    assert "expected acceleration and deceleration times that fit in the move" in example.evaluate().error
    with pytest.raises(CalcError, match=r"^the inputs give no design \(an input error\)$"):
        variants.keep(example)
    missed = variants.follow(json.dumps([{"case": "axis.toml", "edits": [], "values": {"move[1].accel_time": "0.3"}}]),
                             CaseFiles(example.path))
    assert missed == ["variant 1: axis.toml: 1 move: accel time t_a: expected acceleration and deceleration times "
                      "that fit in the move (accel_time + decel_time <= time), found 0.3 s + 0.3 s > 0.5 s"]
    assert variants.kept == []


def test_a_save_the_folder_refuses_says_why_without_the_folder(example):
    folder = example.path.parent
    for path in folder.iterdir():
        path.unlink()
    folder.rmdir()  # the cases' folder gone while the page was open
    example.type_text("mechanism.inertia", "2000")
    with pytest.raises(CalcError, match=r"^save as kept.toml: No such file or directory$"):
        example.save("kept.toml")


def test_an_entry_of_a_table_that_is_no_list_of_tables_says_so():
    with pytest.raises(CalcError, match=r"^a.toml: load\[1\].inertia: the file has no \[\[load\]\] tables$"):
        edited_text('[load]\ninertia = "1 kg*cm**2"\n', [Edit("load[1].inertia", "2 kg*cm**2")], "a.toml")


def test_a_field_left_out_of_the_file_shows_the_value_computed(example):
    # The example leaves the decel time out, so reading it takes the accel time. Accel 0.3 s in a move
    # of 0.7 s: peak speed φ / (t − t_a) = 0.25 rev / (0.7 − 0.3) s = 0.625 rev/s = 37.5 rpm (with the
    # decel field's 0.15 s, as the page used to show it, 0.25 / (0.7 − 0.225) s · 60 = 31.58 rpm).
    assert example.following("move[1].decel_time") == "left out of the file: follows the accel time t_a"
    assert example.following("move[1].jerk_time") is None  # the file writes it
    example.type_text("move[1].time", "0.7")
    example.type_text("move[1].accel_time", "0.3")
    assert example.values["move[1].decel_time"] == 0.3 and example.texts["move[1].decel_time"] == "0.3"
    assert "move[1].decel_time" not in example.changes()  # still left out: the file follows as the screen
    assert results(example)["motion"]["peak_speed"]["value"] == pytest.approx(37.5)
    # Set by the reviewer, it no longer follows, and the file writes it.
    example.type_text("move[1].decel_time", "0.15")
    assert example.changes()["move[1].decel_time"] == (0.15, "s") and example.following("move[1].decel_time") is None
    assert 'decel_time = "0.15 s"' in example.case_text()
    example.type_text("move[1].accel_time", "0.2")
    assert example.values["move[1].decel_time"] == 0.15
    # Undone twice: it follows again.
    example.undo()
    example.undo()
    assert example.values["move[1].decel_time"] == 0.3 and "move[1].decel_time" not in example.changes()


def test_a_saved_file_cannot_be_forged_and_is_read_back(example, tmp_path):
    # A link's mechanism edit carries its words, which the saved file's first comment line holds: newlines in them
    # stay in that line (no TOML from a link), and the file saved reads back as the case on the screen.
    import tomllib

    from calc.review import keep

    forged = 'rotary\n[drive_record]\nfile = "/etc/hostname"\r\n\u2028x'
    example.follow_moves([["mechanism", {"type": "rotary", "inertia": "1500 kg*cm**2", "friction_torque": "4 N*m"},
                           {}, forged]])
    text = example.case_text()
    first, rest = text.split("\n", 1)
    assert first == ('# Changed in the design review from axis.toml: rotary [drive_record] file = "/etc/hostname"'
                     '   x')
    assert "drive_record" not in tomllib.loads(text)
    saved = example.save("forged.toml")
    assert saved.read_text() == text and keep.Written(tmp_path).names() == ["forged.toml"]
    assert evaluate(read_case(saved)).to_json()["verdict"] == results(example)["verdict"]
    # A comment beside a value changed is marked as said of the file's value.
    example.type_text("mechanism.inertia", "3000")
    assert '# (said of the file\'s value 1500 kg*cm**2) J_L at the gearbox output' in example.case_text()


def test_save_refuses_no_change_a_file_too_large_and_more_than_its_count(example, tmp_path, monkeypatch):
    from calc.review import keep

    with pytest.raises(CalcError, match=r"^nothing changed: the screen is axis.toml as it is; nothing written$"):
        example.save("same.toml")
    assert not (tmp_path / "same.toml").exists()
    example.type_text("mechanism.inertia", "2000")
    monkeypatch.setattr(keep, "MAX_CASE_BYTES", 100)
    with pytest.raises(CalcError, match=r"^save as big.toml: the case file would be \d+ bytes, above the 100"):
        example.save("big.toml")
    monkeypatch.setattr(keep, "MAX_CASE_BYTES", 256_000)
    monkeypatch.setattr(keep, "MAX_WRITTEN", 2)
    example.save("one.toml")
    example.save("two.toml")
    with pytest.raises(CalcError, match=r"^save as three.toml: the design review has written 2 files into"):
        example.save("three.toml")
    assert sorted(p.name for p in tmp_path.glob("*.toml")) == ["axis.toml", "one.toml", "two.toml"]
    keep.Written(tmp_path).remove("one.toml")
    example.save("three.toml")
    with pytest.raises(CalcError, match="not a file the design review wrote"):
        keep.Written(tmp_path).remove("axis.toml")
    assert (tmp_path / "axis.toml").exists()


def test_a_file_that_does_not_read_back_is_not_said_saved(example, tmp_path, monkeypatch):
    # What is written is read back: a file whose text, read back, is not the one written is removed, and not saved.
    from pathlib import Path

    example.type_text("mechanism.inertia", "2000")
    real = Path.read_text
    monkeypatch.setattr(Path, "read_text", lambda self, *a, **k: real(self, *a, **k) + "\n[drive_record]\n"
                        if self.name == "lost.toml" else real(self, *a, **k))
    with pytest.raises(CalcError, match=r"^not saved: lost.toml read back"):
        example.save("lost.toml")
    assert not (tmp_path / "lost.toml").exists()


def test_the_unit_switch_shows_and_reads_the_inputs_in_its_system(example):
    # 1 lb·in² = 0.45359237 kg · (0.0254 m)² = 2.9263965e-4 kg·m² (exact by definition of lb and in), so the
    # example's J_L 1500 kg·cm² = 0.15 kg·m² shows as 0.15 / 2.9263965e-4 = 512.576 lb·in², and 600 lb·in² typed is
    # 600 · 2.9263965e-4 = 0.17558379 kg·m² = 1755.8379 kg·cm², which the file keeps in its own unit.
    example.units = "inch-pound"
    assert example.texts["mechanism.inertia"] == "512.576"
    assert example.shown_spec("mechanism.inertia").unit == "lb*in**2"
    assert example.texts["move[1].time"] == "0.5"  # seconds in both systems
    assert not example.type_text("mechanism.inertia", "512.576")  # its own text again: no change by rounding
    assert example.changes() == {}
    assert example.type_text("mechanism.inertia", "600")
    assert example.values["mechanism.inertia"] == pytest.approx(1755.83792, rel=1e-8)
    assert example.texts["mechanism.inertia"] == "600"
    screen = example.evaluate()
    assert screen.texts["mechanism.inertia"] == "600"  # what the field shows (the page compares its fields with it)
    assert screen.changed_texts == {"mechanism.inertia": f"{example.values['mechanism.inertia']:.12g}"}
    assert screen.factors["mechanism.inertia"] == pytest.approx(1 / 2.9263965e-4 / 1e4, rel=1e-7)
    text = example.case_text()
    assert 'inertia = "1755.83792' in text and "kg*cm**2" in text.split('inertia = "1755.83792', 1)[1].split("\n")[0]
    # A value out of the range is refused in the unit shown; back in SI the field shows kg·cm².
    assert example.type_text("mechanism.inertia", "1e9") and "lb·in²" in example.refused["mechanism.inertia"][1]
    example.type_text("mechanism.inertia", "600")
    example.units = "SI"
    assert example.texts["mechanism.inertia"] == "1755.84"
    # The address's values, in the file's unit, give the same screen in a page shown in either system.
    other = ReviewState(example.path)
    other.load()
    other.follow_values(screen.changed_texts)
    assert other.values["mechanism.inertia"] == pytest.approx(example.values["mechanism.inertia"], rel=1e-11)


def test_an_inch_pound_file_shown_in_si_keeps_its_own_units():
    # linear-axis-inch.toml writes its mass in lb: 60 lb = 27.2155 kg shown in SI; 30 kg typed = 66.1387 lb written.
    inch = ReviewState(ROOT / "cases" / "linear-axis-inch.toml")
    inch.load()
    inch.units = "SI"
    assert inch.texts["mechanism.mass"] == "27.2155" and inch.shown_spec("mechanism.mass").unit == "kg"
    assert inch.type_text("mechanism.mass", "30")
    assert inch.values["mechanism.mass"] == pytest.approx(30 / 0.45359237)
    assert inch.changes()["mechanism.mass"][1] == "lb"


def test_a_lead_typed_in_the_unit_shown_is_written_in_the_files(example):
    # The example shown in inch-pound: a ball screw of 0.2 in typed is a lead of 0.2 · 25.4 = 5.08 mm, written in mm.
    example.units = "inch-pound"
    assert example.length_unit() == "in"
    assert example.change_mechanism("ball-screw", "0.2").startswith("mechanism rotary -> ball-screw of 0.2 in")
    assert 'lead = "5.08 mm"' in example.case_text()


def test_each_edit_starts_from_the_file_as_written():
    # The file's parsed text is kept between changes: an edit must never reach the next change's text.
    text = '[motor]\npeak_torque = "12 N*m"  # T_1B\n[load]\ninertia = "1500 kg*cm**2"\n'
    first = edited_text(text, [Edit("motor.peak_torque", "16 N*m")], "a.toml")
    other = edited_text(text, [Edit("load.inertia", "1600 kg*cm**2")], "a.toml")
    assert first == '[motor]\npeak_torque = "16 N*m"  # (said of the file\'s value 12 N*m) T_1B\n[load]\n' \
                    'inertia = "1500 kg*cm**2"\n'
    assert 'peak_torque = "12 N*m"  # T_1B' in other and 'inertia = "1600 kg*cm**2"' in other
    assert edited_text(text, [], "a.toml") == text
