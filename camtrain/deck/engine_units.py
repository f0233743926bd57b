"""Units an engine deck names explicitly beside its values (pressure tables, out-of-balance
moments), with their factors to SI."""

#: Pressure units a table may be written in, with their factor to Pa.
PRESSURE_UNITS = {"bar": 1e5, "MPa": 1e6, "kPa": 1e3, "Pa": 1.0, "psi": 6894.757293168}
#: Moment units of an out-of-balance, with their factor to N m.
MOMENT_UNITS = {"N·m": 1.0, "N·mm": 1e-3}
