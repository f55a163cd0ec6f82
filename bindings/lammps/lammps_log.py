"""The thermo tables of a LAMMPS log, for the plugin's checks, bench and
example plot: `thermo(path)` or `thermo_rows(text)` give one dict per row
(column name -> float), over every `run` in the log."""


def thermo_rows(text):
    rows, cols = [], None
    for line in text.split("\n"):
        s = line.split()
        if s and s[0] == "Step":
            cols = s
            continue
        if cols and len(s) == len(cols):
            try:
                rows.append(dict(zip(cols, map(float, s))))
            except ValueError:
                cols = None
        elif s and s[0] == "Loop":
            cols = None
    return rows


def thermo(path):
    with open(path) as f:
        return thermo_rows(f.read())
