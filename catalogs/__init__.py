"""The technical-data catalogs (CSV), installed as the package data ``calc.catalogs``.

A regular package, not a bare folder: setuptools' editable install maps ``calc.catalogs`` to this
folder only for a package with an ``__init__.py`` (a namespace subpackage mapped outside ``calc/``
does not import there).
"""
