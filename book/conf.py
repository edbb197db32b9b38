"""The course as a static website: the notebooks as stored (never executed here), their math
typeset by a MathJax copy shipped with the build, so the pages need no network.

Build: ``make book`` (``sphinx-build -c book . build/book``); open ``build/book/book/index.html``.
"""

# Imported before the extensions: nbformat's jsonschema would otherwise compile rfc3987_syntax's IRI
# grammars in every build (0.7 s of CPU of 3.9 s; calc.report.publish says why it may go without them).
import calc.report.publish  # noqa: F401

project = "Servo drive-train workbook"
author = "the drivetrain-calc contributors"
copyright = "the drivetrain-calc contributors: text and notebooks CC BY 4.0, code MIT (see Licence and how to cite)"
extensions = ["myst_nb", "sphinx-mathjax-offline"]  # the second copies MathJax into _static/
# The students' book: its pages and the notebooks. The lecturer's (``-t lecturer``, make lecturer) adds
# the worked answers (notebooks/instructor/) and the grading notes under a front page of its own.
LECTURER = tags.has("lecturer")  # noqa: F821 (Sphinx gives conf.py its tags)
root_doc = "book/lecturer" if LECTURER else "book/index"
include_patterns = ["book/index.md", "book/course/*.md", "notebooks/*.ipynb", "notebooks/figures/*"]
include_patterns += ["book/lecturer*.md", "notebooks/instructor/*.ipynb"] if LECTURER else []
exclude_patterns = ["**/.ipynb_checkpoints", ".venv", "build"]
nb_execution_mode = "off"  # the stored outputs, which nbval keeps true
myst_enable_extensions = ["dollarmath", "amsmath"]
nb_merge_streams = True
html_theme = "alabaster"
# sidebar_collapse off: the lecturer's book, whose front page holds the students' as one entry, lists the notebooks too.
html_theme_options = {"nosidebar": False, "page_width": "1100px", "body_max_width": "none", "sidebar_collapse": False}
html_static_path = ["_static"]  # custom.css: wide outputs scroll in their own box
html_title = project
html_show_sourcelink = False
html_copy_source = False
# Tables the notebooks display (the glossary's symbols) write their math as $...$, which JupyterLab
# typesets in any output; MathJax does the same here, in the notebooks' outputs.
mathjax3_config = {
    "tex": {"inlineMath": [["\\(", "\\)"], ["$", "$"]]},
    "options": {"processHtmlClass": "tex2jax_process|mathjax_process|math|output_area|cell_output"},
}
myst_update_mathjax = False  # the configuration above is the whole of it
nb_render_markdown_format = "myst"  # Markdown outputs parsed as the cells are, their $...$ as math
html_extra_path = ["_root"]  # build/book/index.html, the address to open, leads to the front page
