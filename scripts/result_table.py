"""The tools' result tables as the scripts read them.

Every table the tools write (common/csv_writer.h) is a header of bare names,
a '# units: u1,u2,...' line, '#' comment lines, then the rows. numpy and
pandas load it as it is; the plotting scripts want each column keyed
"name [unit]", as the tables' documentation names them.
"""

import csv


def read_rows(lines):
    """The rows of a table (its lines) as dicts keyed "name [unit]" ("name"
    for a column without a unit), and its comment lines without '# '. Tables
    of earlier versions, comments first and units in the header, read too."""
    lines = [line for line in lines if line.strip()]
    comments = [line[1:].strip() for line in lines if line.startswith("#")]
    data = [line for line in lines if not line.startswith("#")]
    header = next(csv.reader([data[0]]))
    units = next((next(csv.reader([c[len("units:"):].strip()]), []) for c in comments
                  if c.startswith("units:")), [])
    comments = [c for c in comments if not c.startswith("units:")]
    units += [""] * (len(header) - len(units))
    names = [f"{n} [{u}]" if u else n for n, u in zip(header, units)]
    return [dict(zip(names, cells)) for cells in csv.reader(data[1:])], comments
