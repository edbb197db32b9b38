"""The calc report notebook and its LaTeX template, installed as the package data ``calc.reports``.

A regular package, not a bare folder: setuptools' editable install maps ``calc.reports`` to this
folder only for a package with an ``__init__.py`` (a namespace subpackage mapped outside ``calc/``
does not import there). The PDFs built here are not package data.
"""
