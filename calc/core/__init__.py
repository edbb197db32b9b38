"""The unit and formula machinery: errors, quantities and their kinds (pint), the formula object
(sympy, with its stored numeric form), checks and the ranking of candidates. Nothing here knows a
gearbox from a coupling."""
