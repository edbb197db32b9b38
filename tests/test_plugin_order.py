"""pytest.ini imports calc.report.publish before the installed plugins (``-p calc.report.publish``), so
that jsonschema, which nbval imports through nbformat as pytest starts, compiles none of the IRI grammars
of rfc3987_syntax (3 s of CPU in every pytest process and worker; calc.report.publish says why). Imported
that early, calc's modules are imported before pytest sets its warning filters; the filter of pytest.ini
(a DeprecationWarning from calc is an error) is checked on that import here instead."""

import os
import subprocess
import sys

from .conftest import ROOT


def test_no_iri_grammar_is_compiled_in_this_process():
    # None where calc.report.publish kept it out (or nothing imported jsonschema); the module, grammars compiled,
    # where jsonschema was imported before it.
    assert sys.modules.get("rfc3987_syntax") is None, "jsonschema was imported before pytest.ini's -p"


def test_the_modules_imported_before_the_plugins_raise_no_deprecation_warning():
    # pytest.ini's filter, `error::DeprecationWarning:calc.*`, on the import pytest.ini's -p makes.
    code = ("import warnings\nwarnings.filterwarnings('error', category=DeprecationWarning, module='calc.*')\n"
            "import calc.report.publish\nprint(calc.report.publish.__file__)")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip() == str(ROOT / "calc" / "report" / "publish.py")
