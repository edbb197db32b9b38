"""The checkpoint's autograder (Otter-Grader, exception-based test file): each item of a student's
checkpoint notebook against the package's value for that student's brief, drawn again from the
roster's name and the course's seed (calc.course.variants). The lecturer's build writes the seed
in and zips this file (``make lecturer``: build/lecturer/grading/autograder.zip)."""

from otter.test_files import test_case

OK_FORMAT = False
name = "checkpoint"
SEED = 0  # set by the lecturer's build


def _mark(env, item):
    """The mark of one item: passes, or fails with a message that never gives the key."""
    from calc.course.checkpoint import expected, graded, student_of, submitted_from
    from calc.course.variants import variant

    key = expected(variant(student_of(env), SEED))
    mark = {m.item.name: m for m in graded(submitted_from(env), key)}[item]
    assert mark.passes, mark.message


@test_case(points=1)
def n_2max(env):
    _mark(env, "n_2max")


@test_case(points=1)
def T_peak(env):
    _mark(env, "T_peak")


@test_case(points=1)
def ED(env):
    _mark(env, "ED")


@test_case(points=1)
def mode(env):
    _mark(env, "mode")


@test_case(points=1)
def T_2m(env):
    _mark(env, "T_2m")


@test_case(points=1)
def motor(env):
    _mark(env, "motor")


@test_case(points=1)
def gearbox(env):
    _mark(env, "gearbox")
