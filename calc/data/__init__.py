"""Technical data read from files: the makers' catalogs (``catalogs/*.csv``), the factor tables and
measurements (hysteresis loops, transmission traces, speed-torque curves)."""
