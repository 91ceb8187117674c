#!/usr/bin/env python3
"""Reference conversions of the files in this folder into the data pack's
wavelength_nm,n,k CSV, written once by hand with PyYAML and plain Python,
independently of the C readers, so test_cli_import.sh can compare F0 through both
routes. Formulas as the refractiveindex.info documentation defines them
(database/doc/Dispersion formulas); a formula is sampled every 1 nm over
360-830 nm inside its wavelength_range, a k table interpolated
linearly there and held at its ends. Run: python3 make_reference.py"""
import math, sys, yaml

def formula(t, c, um):
    c = list(c) + [0.0] * (17 - len(c))
    C = lambda i: c[i - 1]
    l2 = um * um
    if t == 1:
        v = 1 + C(1) + sum(C(2 * i) * l2 / (l2 - C(2 * i + 1) ** 2) for i in range(1, 9))
        return math.sqrt(v)
    if t == 2:
        v = 1 + C(1) + sum(C(2 * i) * l2 / (l2 - C(2 * i + 1)) for i in range(1, 9))
        return math.sqrt(v)
    if t == 3:
        return math.sqrt(C(1) + sum(C(2 * i) * um ** C(2 * i + 1) for i in range(1, 9)))
    if t == 4:
        v = C(1) + C(2) * um ** C(3) / (l2 - C(4) ** C(5)) + C(6) * um ** C(7) / (l2 - C(8) ** C(9))
        v += sum(C(2 * i) * um ** C(2 * i + 1) for i in range(5, 9))
        return math.sqrt(v)
    if t == 5:
        return C(1) + sum(C(2 * i) * um ** C(2 * i + 1) for i in range(1, 6))
    if t == 6:
        return 1 + C(1) + sum(C(2 * i) / (C(2 * i + 1) - um ** -2) for i in range(1, 6))
    if t == 7:
        d = l2 - 0.028
        return C(1) + C(2) / d + C(3) / d ** 2 + C(4) * l2 + C(5) * l2 ** 2 + C(6) * l2 ** 3
    if t == 8:
        a = C(1) + C(2) * l2 / (l2 - C(3)) + C(4) * l2
        return math.sqrt((1 + 2 * a) / (1 - a))
    if t == 9:
        return math.sqrt(C(1) + C(2) / (l2 - C(3)) + C(4) * (um - C(5)) / ((um - C(5)) ** 2 + C(6)))
    raise ValueError(t)

def interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            u = (x - xs[i]) / (xs[i + 1] - xs[i])
            return (1 - u) * ys[i] + u * ys[i + 1]

def rows_of(block):
    return [[float(w) for w in line.split()] for line in block.strip().splitlines()]

def convert(path):
    doc = yaml.safe_load(open(path, encoding="utf-8"))
    n_rows = k_rows = f = None
    for d in doc["DATA"]:
        t = d["type"]
        if t == "tabulated nk":
            r = rows_of(d["data"])
            n_rows = [(x[0] * 1000, x[1]) for x in r]
            k_rows = [(x[0] * 1000, x[2]) for x in r]
        elif t == "tabulated n":
            n_rows = [(x[0] * 1000, x[1]) for x in rows_of(d["data"])]
        elif t == "tabulated k":
            k_rows = [(x[0] * 1000, x[1]) for x in rows_of(d["data"])]
        else:
            lo, hi = (float(v) * 1000 for v in str(d["wavelength_range"]).split())
            f = (int(t.split()[1]), [float(v) for v in str(d["coefficients"]).split()], lo, hi)
    out = []
    if f:
        t, c, lo, hi = f
        for i in range(471):
            nm = 360.0 + i
            if lo - 1e-9 <= nm <= hi + 1e-9:
                k = interp([r[0] for r in k_rows], [r[1] for r in k_rows], nm) if k_rows else 0.0
                out.append((nm, formula(t, c, nm / 1000), k))
    else:
        out = [(w, n, k) for (w, n), (_, k) in zip(n_rows, k_rows)]
    with open(path.rsplit(".", 1)[0] + ".reference.csv", "w") as o:
        o.write("wavelength_nm,n,k\n")
        for w, n, k in out:
            o.write("%.10g,%.10g,%.10g\n" % (w, n, k))

for p in sys.argv[1:] or ["Au-Johnson.yml", "TiN-Pfluger.yml", "N-BK7.yml", "BOROFLOAT33.yml", "E-LLF2.yml",
                          "TiO2-Devore-o.yml", "PMMA-495-specs.yml", "Ar-Peck-15C.yml", "herzberger-constructed.yml",
                          "TlCl-Schroter.yml", "urea-Rosker-e.yml"]:
    convert(p)

# The other formats, constructed from the same Johnson & Christy gold rows
# (and N-BK7's formula), each with its reference CSV.
HC = 1239.8419843320026  # eV nm
au = [(r[0] * 1000, r[1], r[2]) for r in rows_of(yaml.safe_load(open("Au-Johnson.yml"))["DATA"][0]["data"])]
au_wl = [r[0] for r in au]

def write_reference(name, rows):
    with open(name, "w") as o:
        o.write("wavelength_nm,n,k\n")
        for w, n, k in sorted(rows):
            o.write("%.10g,%.10g,%.10g\n" % (w, n, k))

# refractiveindex.info CSV export, two blocks (um)
with open("Au-Johnson.export.csv", "w") as o:
    o.write("wl,n\n" + "".join("%.4f,%.4g\n" % (w / 1000, n) for w, n, k in au))
    o.write("wl,k\n" + "".join("%.4f,%.4g\n" % (w / 1000, k) for w, n, k in au))
write_reference("Au-Johnson.export.reference.csv", [(float("%.4f" % (w / 1000)) * 1000, n, k) for w, n, k in au])

# refractiveindex.info CSV export, one wl,n,k block (um), from N-BK7's reference rows
bk7 = [tuple(float(v) for v in line.split(",")) for line in open("N-BK7.reference.csv").read().split("\n")[1:] if line]
with open("N-BK7.export.csv", "w") as o:
    o.write("wl,n,k\n" + "".join("%.4f,%.8f,%.5g\n" % (w / 1000, n, k) for w, n, k in bk7[::10]))
write_reference("N-BK7.export.reference.csv",
                [(float("%.4f" % (w / 1000)) * 1000, float("%.8f" % n), float("%.5g" % k)) for w, n, k in bk7[::10]])

# SOPRA, eV (unit 1) and nm (unit 4): gold interpolated onto the file's uniform grid
def sopra(name, unit, start, end, intervals):
    rows = []
    with open(name, "w") as o:
        o.write("%d\t%g\t%g\t%d\n" % (unit, start, end, intervals))
        for i in range(intervals + 1):
            x = start + (end - start) * i / intervals
            nm = HC / x if unit == 1 else x
            n = round(interp(au_wl, [r[1] for r in au], nm), 5)
            k = round(interp(au_wl, [r[2] for r in au], nm), 5)
            o.write("%.5f\t%.5f\n" % (n, k))
            rows.append((nm, n, k))
    write_reference(name.rsplit(".", 1)[0] + ".reference.csv", rows)

sopra("Au-eV.nk", 1, 1.4, 3.6, 44)
sopra("Au-nm.nk", 4, 350, 850, 50)

# Mitsuba-style .spd pair (nm), with comment lines as Mitsuba's files have
with open("Au.eta.spd", "w") as o:
    o.write("# gold, Johnson & Christy 1972 (refractiveindex.info Au/Johnson.yml)\n# wavelength_nm n\n")
    o.write("".join("%.1f %.4g\n" % (w, n) for w, n, k in au))
with open("Au.k.spd", "w") as o:
    o.write("# gold, Johnson & Christy 1972\n# wavelength_nm k\n")
    o.write("".join("%.1f %.4g\n" % (w, k) for w, n, k in au))
write_reference("Au.spd.reference.csv", au)
