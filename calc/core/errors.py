"""The one exception type of the package.

Every message is one sentence that names where the bad value came from (file, key, catalog
row and column, or argument), what was expected and what was found.
"""


class CalcError(ValueError):
    """Bad input: a value, unit, file or catalog that the calculation cannot use."""
